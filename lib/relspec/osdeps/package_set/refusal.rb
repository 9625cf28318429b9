# frozen_string_literal: true

require_relative "../reader"

# How relspec's package set stops an autoproj run: one message naming the
# file and the entry, as autoproj's configuration error.
module RelspecPackageSet
  def self.refuse(message)
    raise Autoproj::ConfigError, "relspec package set: #{message}"
  end

  # A YAML file of the package set or the workspace: plain data only
  # (Osdeps::Reader); a file that is not YAML is refused with its name.
  def self.read_yaml(path, empty)
    read = Relspec::Osdeps::Reader.yaml(File.read(path), empty: empty)
    refuse("#{path}: #{read.reason}") unless read.ok?
    read.value
  end
end
