/*
 * Control-file syntax (deb822) in C, for large apt indices: a Packages file
 * of Debian's archive has 60,000 stanzas, and the pure Ruby reader spends
 * most of its time walking lines. Same semantics as Relspec::Apt::Deb822.parse:
 *
 * - lines starting with '#' are comments;
 * - a line of only white space ends a stanza;
 * - a line starting with a space or a tab continues the previous field
 *   ("\n" + the line as written);
 * - "Name: value": the value is stripped of surrounding white space; a name
 *   is non-empty and has no space; a name may appear once per stanza;
 * - "\r\n" line ends are read as "\n".
 */
#include <ruby.h>
#include <ruby/encoding.h>
#include <string.h>

static VALUE parse_error_class(void)
{
    VALUE relspec = rb_const_get(rb_cObject, rb_intern("Relspec"));
    VALUE apt = rb_const_get(relspec, rb_intern("Apt"));
    VALUE deb822 = rb_const_get(apt, rb_intern("Deb822"));
    return rb_const_get(deb822, rb_intern("ParseError"));
}

static void raise_parse_error(const char *message, long line)
{
    VALUE error = rb_funcall(parse_error_class(), rb_intern("new"), 2, rb_utf8_str_new_cstr(message), LONG2NUM(line));
    rb_exc_raise(error);
}

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' || c == '\0';
}

static int blank(const char *start, const char *end)
{
    for (const char *p = start; p < end; p++)
        if (!is_space(*p)) return 0;
    return 1;
}

static VALUE stripped(const char *start, const char *end)
{
    while (start < end && is_space(*start)) start++;
    while (end > start && is_space(end[-1])) end--;
    return rb_utf8_str_new(start, end - start);
}

/*
 * Walks every line. With +wanted+ (an Array of field names) only those
 * fields are kept and no error is raised for lines it does not need to
 * understand; without it, every field is kept and malformed lines raise.
 * Returns [stanzas, lines]: an Array of Hashes and the Array of the line
 * each stanza starts on (two flat arrays: no small Array per stanza).
 */
static void emit(VALUE stanzas, VALUE lines, VALUE fields, long first_line, int yielding)
{
    if (yielding) {
        rb_yield_values(2, fields, LONG2NUM(first_line));
    } else {
        rb_ary_push(stanzas, fields);
        rb_ary_push(lines, LONG2NUM(first_line));
    }
}

static VALUE walk(VALUE text, VALUE wanted, int strict)
{
    int yielding = rb_block_given_p();
    /* the text must not change while it is walked (a block could) */
    text = rb_str_new_frozen(text);
    Check_Type(text, T_STRING);
    const char *data = RSTRING_PTR(text);
    const char *end = data + RSTRING_LEN(text);
    VALUE stanzas = rb_ary_new();
    VALUE lines = rb_ary_new();
    VALUE fields = Qnil;
    VALUE last = Qnil; /* the key of the field continuation lines belong to, or Qnil */
    int in_field = 0;   /* a field line was seen in this stanza (for strict errors) */
    long first_line = 0;
    long number = 0;
    long wanted_count = NIL_P(wanted) ? 0 : RARRAY_LEN(wanted);

    const char *line = data;
    while (line <= end) {
        const char *stop = memchr(line, '\n', end - line);
        if (!stop) stop = end;
        const char *line_end = stop;
        if (line_end > line && line_end[-1] == '\r') line_end--;
        number++;

        if (line == end) {
            /* after the final newline */
        } else if (blank(line, line_end)) {
            if (!NIL_P(fields)) emit(stanzas, lines, fields, first_line, yielding);
            fields = Qnil;
            last = Qnil;
            in_field = 0;
        } else if (*line == '#') {
            /* comment */
        } else if (*line == ' ' || *line == '\t') {
            if (!in_field) {
                if (strict) raise_parse_error("continuation line outside of a field", number);
            } else if (!NIL_P(last)) {
                VALUE value = rb_hash_aref(fields, last);
                rb_str_cat(value, "\n", 1);
                rb_str_cat(value, line, line_end - line);
            }
        } else {
            const char *colon = memchr(line, ':', line_end - line);
            const char *space = memchr(line, ' ', line_end - line);
            if (!colon || colon == line || (space && space < colon)) {
                if (strict) {
                    char message[160];
                    long shown = line_end - line > 60 ? 60 : line_end - line;
                    VALUE inspected = rb_inspect(rb_utf8_str_new(line, shown));
                    snprintf(message, sizeof(message), "expected \"Field: value\", found %s", StringValueCStr(inspected));
                    raise_parse_error(message, number);
                }
                /* still a stanza: one without the wanted fields tells the
                 * caller to look closer (with the strict parser) */
                if (NIL_P(fields)) {
                    fields = rb_hash_new();
                    first_line = number;
                }
                last = Qnil;
            } else {
                if (NIL_P(fields)) {
                    fields = rb_hash_new();
                    first_line = number;
                }
                in_field = 1;
                VALUE name = Qnil;
                if (NIL_P(wanted)) {
                    /* field names repeat in every stanza: share one frozen string */
                    name = rb_enc_interned_str(line, colon - line, rb_utf8_encoding());
                } else {
                    for (long i = 0; i < wanted_count; i++) {
                        VALUE candidate = RARRAY_AREF(wanted, i);
                        if (RSTRING_LEN(candidate) == colon - line && memcmp(RSTRING_PTR(candidate), line, colon - line) == 0) {
                            name = candidate;
                            break;
                        }
                    }
                }
                if (!NIL_P(name)) {
                    if (strict && rb_hash_lookup2(fields, name, Qundef) != Qundef) {
                        char message[160];
                        snprintf(message, sizeof(message), "field %.*s appears twice in one stanza", (int)(colon - line > 100 ? 100 : colon - line), line);
                        raise_parse_error(message, number);
                    }
                    /* Take the continuation lines with the field in one string
                     * when they can be copied as they are (no "\r", no trailing
                     * space on the first line): one allocation for a long
                     * Description instead of one per line. */
                    const char *value_end = line_end;
                    const char *next = stop;
                    long extra = 0;
                    int copyable = !(line_end > colon + 1 && is_space(line_end[-1]));
                    while (copyable && next < end && (next[1] == ' ' || next[1] == '\t')) {
                        const char *following = memchr(next + 1, '\n', end - next - 1);
                        if (!following) following = end;
                        if (following > next + 1 && following[-1] == '\r') { copyable = 0; break; }
                        if (blank(next + 1, following)) break;
                        value_end = following;
                        next = following;
                        extra++;
                    }
                    if (copyable && extra > 0) {
                        const char *value_start = colon + 1;
                        while (value_start < line_end && is_space(*value_start)) value_start++;
                        rb_hash_aset(fields, name, rb_utf8_str_new(value_start, value_end - value_start));
                        number += extra;
                        last = Qnil;
                        if (next == end) { stop = end; break; }
                        line = next + 1;
                        continue;
                    }
                    rb_hash_aset(fields, name, stripped(colon + 1, line_end));
                }
                last = name;
            }
        }
        if (stop == end) break;
        line = stop + 1;
    }
    if (!NIL_P(fields)) emit(stanzas, lines, fields, first_line, yielding);
    RB_GC_GUARD(text);
    return yielding ? Qnil : rb_ary_new_from_args(2, stanzas, lines);
}

/* Relspec::Apt::Native.parse(text) -> [[fields, ...], [line, ...]];
 * with a block, yields (fields, line) for each stanza instead. */
static VALUE native_parse(VALUE self, VALUE text)
{
    return walk(text, Qnil, 1);
}

/* Relspec::Apt::Native.scan(text, fields) -> [[fields, ...], [line, ...]] with only +fields+ */
static VALUE native_scan(VALUE self, VALUE text, VALUE wanted)
{
    Check_Type(wanted, T_ARRAY);
    VALUE keys = rb_ary_new_capa(RARRAY_LEN(wanted));
    for (long i = 0; i < RARRAY_LEN(wanted); i++) {
        VALUE key = rb_str_dup(rb_String(RARRAY_AREF(wanted, i)));
        rb_ary_push(keys, rb_str_freeze(key));
    }
    return walk(text, keys, 0);
}

void Init_relspec_deb822(void)
{
    VALUE relspec = rb_define_module("Relspec");
    VALUE apt = rb_define_module_under(relspec, "Apt");
    VALUE native = rb_define_module_under(apt, "Native");
    rb_define_module_function(native, "parse", native_parse, 1);
    rb_define_module_function(native, "scan", native_scan, 2);
}
