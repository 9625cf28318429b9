# frozen_string_literal: true

module Relspec
  VERSION = "0.1.0"
end
