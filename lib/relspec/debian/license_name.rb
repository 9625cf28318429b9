# frozen_string_literal: true

module Relspec
  module Debian
    # The DEP-5 short name (https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/#license-short-name)
    # of a license as manifest.xml or a gemspec writes it in free text
    # ("LGPL v2 or later", "New BSD License", "CeCILL-B (BSD-like)"). The
    # free text itself stays in the license paragraph; a text no rule knows
    # is kept when it is one word (a name), else it becomes "other".
    module LicenseName
      # [pattern over the normalised text (lowercase, single spaces), short name]; first match wins
      RULES = [
        [/\A(gnu )?(lesser|library) general public license,? v(ersion)? ?2\.1 or later/, "LGPL-2.1+"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?2\.1 ?(\+|or (any )?later)/, "LGPL-2.1+"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?2\.1\b/, "LGPL-2.1"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?2 ?(\+|or (any )?later)/, "LGPL-2+"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?2\b/, "LGPL-2"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?3 ?(\+|or (any )?later)/, "LGPL-3+"],
        [/\A(gnu )?lgpl[ -]?v?(ersion)? ?3\b/, "LGPL-3"],
        [/\A(gnu )?gpl[ -]?v?(ersion)? ?2 ?(\+|or (any )?later)/, "GPL-2+"],
        [/\A(gnu )?gpl[ -]?v?(ersion)? ?2\b/, "GPL-2"],
        [/\A(gnu )?gpl[ -]?v?(ersion)? ?3 ?(\+|or (any )?later)/, "GPL-3+"],
        [/\A(gnu )?gpl[ -]?v?(ersion)? ?3\b/, "GPL-3"],
        [/\A(new|modified|revised) bsd|\Absd[ -]?3|\A3-clause bsd|\Absd license\z|\Absd\z/, "BSD-3-clause"],
        [/\Absd[ -]?2|\A(simplified|2-clause) bsd|\Afreebsd/, "BSD-2-clause"],
        [/\A(mit|expat)\b/, "Expat"],
        [/\Aapache[ -]?(license)?,? ?(v|version ?)?2/, "Apache-2.0"],
        [/\Ampl[ -]?(v|version ?)?2/, "MPL-2.0"],
        [/\Acecill[ -]b\b/, "CeCILL-B"],
        [/\Acecill[ -]c\b/, "CeCILL-C"],
        [/\Aruby\b/, "Ruby"],
        [/\Apublic domain/, "public-domain"]
      ].freeze

      # Short names whose full text Debian ships in /usr/share/common-licenses
      # (the paragraph points there instead of repeating the text).
      COMMON = { "LGPL-2" => "LGPL-2", "LGPL-2+" => "LGPL-2", "LGPL-2.1" => "LGPL-2.1", "LGPL-2.1+" => "LGPL-2.1",
                 "LGPL-3" => "LGPL-3", "LGPL-3+" => "LGPL-3", "GPL-2" => "GPL-2", "GPL-2+" => "GPL-2",
                 "GPL-3" => "GPL-3", "GPL-3+" => "GPL-3", "Apache-2.0" => "Apache-2.0", "MPL-2.0" => "MPL-2.0" }.freeze

      module_function

      def of(text)
        normalised = text.to_s.strip.downcase.gsub(/\s+/, " ")
        return "other" if normalised.empty?

        RULES.each { |pattern, name| return name if normalised.match?(pattern) }
        word = text.strip
        word.match?(/\A[A-Za-z][\w.+-]+\z/) ? word : "other"
      end

      # The file under /usr/share/common-licenses for +short+, or nil.
      def common_license_file(short)
        COMMON[short] && "/usr/share/common-licenses/#{COMMON[short]}"
      end
    end
  end
end
