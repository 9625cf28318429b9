# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Osdeps
    # The armored public key of a signing key id, from the gpg keyring
    # relspec publishes with (GNUPGHOME): what users' apt checks the
    # repository's Release against (signed-by=).
    module PublicKey
      module_function

      def export(key_id)
        output, error, status = Open3.capture3("gpg", "--batch", "--armor", "--export", key_id)
        return output if status.success? && output.include?("BEGIN PGP PUBLIC KEY BLOCK")

        raise ToolError, "gpg --export #{key_id} gave no public key: #{error.strip.lines.last(3).join.strip}"
      rescue SystemCallError => e
        raise ToolError, "cannot run gpg: #{e.message.sub(/ @ .*/, '')} (install the gnupg package)"
      end
    end
  end
end
