# frozen_string_literal: true

# A folder on a file system of its own that cannot take a file: a tiny
# tmpfs, filled up (ENOSPC) or mounted read-only (EROFS), mounted in a
# private mount namespace of the one command that sees it (`unshare -rm`:
# a user namespace too, so no root is needed, and the machine's mounts are
# never touched). Root ignores mode bits, so a read-only folder cannot be
# made with chmod; this is the real failure a full or read-only disk gives.
module FullFilesystem
  module_function

  # The command prefix that runs its last arguments with +dir+ (which
  # must exist) as such a file system: +state+ :full or :read_only.
  def command(dir, state)
    mount = case state
            when :full then 'mount -t tmpfs -o size=64k tmpfs "$0" && { head -c 1M /dev/zero >"$0/fill" 2>/dev/null || :; }'
            when :read_only then 'mount -t tmpfs -o ro,size=64k tmpfs "$0"'
            else raise ArgumentError, "unknown state #{state.inspect}"
            end
    ["unshare", "-rm", "--", "sh", "-ec", "#{mount}; exec \"$@\"", dir]
  end

  # Whether this machine lets a user make such a namespace.
  def available?
    system("unshare", "-rm", "--", "true", out: File::NULL, err: File::NULL)
  end
end
