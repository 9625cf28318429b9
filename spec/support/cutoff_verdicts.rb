# frozen_string_literal: true

require "relspec/builder/build_results"

# A stand-in for the run's Abi::InterfaceVerdicts in the unit specs of the
# early cutoff's run side (EarlyCutoff, Slurm::HeldCandidates), which test
# what is done with a verdict, not how one is reached (InterfaceVerdicts has
# its own spec): keep(entry) keeps the candidates named in +keeps+ and has
# the others rebuilt; revoke records in +revoked+; +deciding+ answers
# deciding?.
CutoffVerdicts = Struct.new(:keeps, :revoked, :deciding) do
  def keep(entry)
    return nil unless entry.cutoff

    Relspec::Builder::BuildResults::Cutoff.new(keeps: "1-1", verdict: keeps.include?(entry.source) ? "keep" : "rebuild",
                                               reason: "r", evidence: [])
  end

  def revoke(source, reason)
    revoked << [source, reason]
  end

  def deciding? = deciding
end
