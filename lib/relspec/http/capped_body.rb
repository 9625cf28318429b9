# frozen_string_literal: true

module Relspec
  module Http
    # Reads an HTTP answer's body in pieces, stopping at a size cap: an
    # endless or oversized body ends in an error the caller words, never in
    # NoMemoryError. Shared by the apt fetcher and the Launchpad client.
    module CappedBody
      # The body is larger than the cap.
      class TooLarge < StandardError; end

      module_function

      # The body of +response+ (a Net::HTTPResponse being read), binary;
      # raises TooLarge past +max_bytes+.
      def read(response, max_bytes)
        raise TooLarge if response.content_length.to_i > max_bytes

        body = String.new(capacity: [response.content_length || 0, max_bytes].min, encoding: Encoding::BINARY)
        response.read_body do |chunk|
          raise TooLarge if body.bytesize + chunk.bytesize > max_bytes

          body << chunk
        end
        body
      end
    end
  end
end
