#include "studies/contract/Study.hpp"

#include <stdexcept>

namespace granwave {

RunSet::RunSet(std::vector<RunRecord> records) : records_(std::move(records)) {
  for (std::size_t i = 0; i < records_.size(); ++i) index_[records_[i].request.label] = i;
}

const RunRecord& RunSet::get(const std::string& label) const {
  const auto it = index_.find(label);
  if (it == index_.end()) throw std::logic_error("study asked for an unplanned run: " + label);
  return records_[it->second];
}

}  // namespace granwave
