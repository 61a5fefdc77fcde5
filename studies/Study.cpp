#include "studies/Study.hpp"

#include <fmt/format.h>

#include "studies/EffectiveRestitutionStudy.hpp"
#include "studies/MomentumTransferStudy.hpp"
#include "studies/SoundSpeedStudy.hpp"
#include "studies/StabilityStudy.hpp"
#include "studies/WaveFrontsStudy.hpp"

namespace granwave {

RunSet::RunSet(std::vector<RunRecord> records) : records_(std::move(records)) {
  for (std::size_t i = 0; i < records_.size(); ++i) index_[records_[i].request.label] = i;
}

const RunRecord& RunSet::get(const std::string& label) const {
  const auto it = index_.find(label);
  if (it == index_.end()) throw std::logic_error("study asked for an unplanned run: " + label);
  return records_[it->second];
}

std::unique_ptr<Study> makeStudy(StudyFile& file) {
  const std::string& kind = file.kind();
  if (kind == "wave-fronts") return makeWaveFrontsStudy(file);
  if (kind == "effective-restitution") return makeEffectiveRestitutionStudy(file);
  if (kind == "sound-speed") return makeSoundSpeedStudy(file);
  if (kind == "stability") return makeStabilityStudy(file);
  if (kind == "momentum-transfer") return makeMomentumTransferStudy(file);
  file.fail("study", "kind",
            "unknown study kind; valid kinds: wave-fronts, sound-speed, effective-restitution, "
            "momentum-transfer, stability");
}

}  // namespace granwave
