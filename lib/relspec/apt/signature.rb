# frozen_string_literal: true

require "open3"
require "tmpdir"

module Relspec
  module Apt
    # Checks repository signatures with gpgv against one keyring, and reads
    # the content of clearsigned files (InRelease) when they are trusted
    # without a key.
    module Signature
      # Raised when a signature does not verify.
      class Invalid < StandardError; end

      module_function

      # The verified content of a clearsigned InRelease.
      def verify_clearsigned(bytes, keyring)
        Dir.mktmpdir("relspec-gpgv") do |dir|
          signed = File.join(dir, "InRelease")
          File.binwrite(signed, bytes)
          output = File.join(dir, "content")
          run_gpgv(keyring, "--output", output, signed)
          File.binread(output)
        end
      end

      # Checks a detached Release.gpg against Release.
      def verify_detached(content, signature, keyring)
        Dir.mktmpdir("relspec-gpgv") do |dir|
          File.binwrite(File.join(dir, "Release"), content)
          File.binwrite(File.join(dir, "Release.gpg"), signature)
          run_gpgv(keyring, File.join(dir, "Release.gpg"), File.join(dir, "Release"))
        end
        content
      end

      ARMOR = "-----BEGIN PGP PUBLIC KEY BLOCK-----"

      def run_gpgv(keyring, *args)
        Dir.mktmpdir("relspec-keyring") do |dir|
          _out, err, status = Open3.capture3("gpgv", "--keyring", binary_keyring(keyring, dir), *args)
          return if status.success?

          fail_with(err)
        end
      rescue Errno::ENOENT
        raise Invalid, "gpgv is not installed (Debian package gpgv)"
      end

      # gpgv reads binary keyrings only and says "No public key" for an
      # armored one (keys/*.asc): those are dearmored into +dir+ first.
      def binary_keyring(keyring, dir)
        path = File.expand_path(keyring)
        head = File.file?(path) ? File.open(path, "rb") { |file| file.read(256) }.to_s : ""
        return path unless head.lstrip.start_with?(ARMOR)

        binary = File.join(dir, "keyring.gpg")
        _out, err, status = Open3.capture3("gpg", "--homedir", dir, "--batch", "--quiet", "--dearmor",
                                           "--output", binary, path)
        raise Invalid, "#{keyring}: cannot read the armored keyring: #{err.strip}" unless status.success?

        binary
      rescue Errno::ENOENT
        raise Invalid, "#{keyring} is an armored keyring and gpg (to dearmor it) is not installed: " \
                       "give a binary keyring (gpg --dearmor)"
      end

      def fail_with(err)
        reason = err.lines.grep(/BAD signature|Can't check signature|no valid OpenPGP data|keyblock resource/).first
        raise Invalid, (reason || err.lines.last || "gpgv failed").strip.sub(/\Agpgv: /, "")
      end

      # The signed text of a clearsigned message, without checking anything.
      def unarmor(bytes)
        text = bytes.dup.force_encoding(Encoding::UTF_8)
        return text unless text.start_with?("-----BEGIN PGP SIGNED MESSAGE-----")

        body = text.split(/\r?\n\r?\n/, 2)[1].to_s
        body = body.split(/^-----BEGIN PGP SIGNATURE-----/, 2).first.to_s
        body.gsub(/^- /, "")
      end
    end
  end
end
