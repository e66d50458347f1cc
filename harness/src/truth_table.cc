#include "hil/harness/truth_table.h"

#include <algorithm>
#include <stdexcept>

namespace hil::harness {

TruthTable::TruthTable(const truth::TruthConfig& config, std::vector<Time> times)
    : times_(std::move(times)), frame_(config.origin) {
  std::erase_if(times_, [](Time t) { return t < Time{}; });
  std::sort(times_.begin(), times_.end());
  times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
  samples_.reserve(times_.size());
  truth::TruthIntegrator truth(config);
  for (const Time t : times_) samples_.push_back(truth.Sample(t));
}

bool TruthTable::Has(Time t) const { return std::binary_search(times_.begin(), times_.end(), t); }

const TruthSample& TruthTable::At(Time t) const {
  const auto it = std::lower_bound(times_.begin(), times_.end(), t);
  if (it == times_.end() || *it != t) throw std::out_of_range("truth table: no sample at the time asked");
  return samples_[static_cast<std::size_t>(it - times_.begin())];
}

}  // namespace hil::harness
