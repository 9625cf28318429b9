# frozen_string_literal: true

require "open3"

# A gpg signing key without a passphrase in its own GNUPGHOME, as a
# release's build machine has one (repository.sign_with).
class SigningKey
  attr_reader :home, :fingerprint

  # +home+: an empty folder with mode 0700.
  def initialize(home)
    @home = home
    output, status = Open3.capture2e(env, "gpg", "--batch", "--passphrase", "", "--quick-gen-key",
                                     "Relspec Test <test@example.org>", "future-default", "sign", "never")
    raise output unless status.success?

    output, = Open3.capture2e(env, "gpg", "--batch", "--list-secret-keys", "--with-colons")
    @fingerprint = output[/^fpr:+(\h{40}):/, 1]
  end

  def env
    { "GNUPGHOME" => @home }
  end

  # The public key, binary (what repository.keyring names).
  def public_keyring
    IO.popen(env, ["gpg", "--export", fingerprint], &:read)
  end

  # Stops the gpg-agent gpg started for +home+.
  def stop
    system(env, "gpgconf", "--kill", "gpg-agent", out: File::NULL, err: File::NULL)
  end
end
