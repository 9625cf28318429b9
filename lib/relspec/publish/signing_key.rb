# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Publish
    # The key of `repository.sign_with` must be a secret key of the gpg
    # keyring reprepro will use (GNUPGHOME): checked before anything is
    # included, so that a missing key stops the publication with gpg's own
    # words instead of leaving packages included but the Release unsigned.
    module SigningKey
      module_function

      def check(key_id)
        output, status = Open3.capture2e("gpg", "--batch", "--list-secret-keys", "--with-colons", key_id)
        return if status.success? && output.match?(/^sec:/)

        raise PublishError, "gpg --list-secret-keys #{key_id} failed (exit status #{status.exitstatus}): " \
                            "#{output.lines.last(5).join.strip}\nrepository.sign_with names a key that is not a secret " \
                            "key of this user's gpg keyring (GNUPGHOME); import it or fix the key id"
      rescue SystemCallError => e
        raise PublishError, "cannot run gpg: #{e.message.sub(/ @ .*/, '')} (install the gnupg package)"
      end
    end
  end
end
