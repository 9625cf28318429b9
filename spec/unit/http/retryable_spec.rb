# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/http/retryable"
require "net/http"

RSpec.describe Relspec::Http::Retryable do
  now = Time.utc(2026, 1, 2, 3, 4, 5)

  def response(code, retry_after = nil)
    answer = Net::HTTPResponse::CODE_TO_OBJ.fetch(code).new("1.1", code, "Reason")
    answer["Retry-After"] = retry_after if retry_after
    answer
  end

  it "names the answer and reads Retry-After in seconds" do
    error = described_class.answer(response("503", " 12 "), now: now)
    expect(error.message).to eq("HTTP 503 Reason")
    expect(error.retry_after).to eq(12)
  end

  it "reads an HTTP-date Retry-After as the seconds until then, never negative" do
    expect(described_class.answer(response("429", "Fri, 02 Jan 2026 03:05:05 GMT"), now: now).retry_after).to eq(60)
    expect(described_class.answer(response("429", "Fri, 02 Jan 2026 03:00:00 GMT"), now: now).retry_after).to eq(0)
  end

  it "takes a missing, empty or unreadable Retry-After as no wish" do
    expect(described_class.answer(response("500"), now: now).retry_after).to be_nil
    expect(described_class.answer(response("500", ""), now: now).retry_after).to be_nil
    expect(described_class.answer(response("500", "soon"), now: now).retry_after).to be_nil
    expect(described_class.answer(response("500", "-5"), now: now).retry_after).to be_nil
  end
end
