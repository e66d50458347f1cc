// The default criteria's table (default_criteria.h); the report judges a run on them
// (report/default_criteria.cc).
#include "hil/harness/scenario/default_criteria.h"

namespace hil::harness {

const DefaultCriterionSpec* FindDefaultCriterion(const std::string& key) {
  for (const DefaultCriterionSpec& d : kDefaultCriteria) {
    if (key == d.key) return &d;
  }
  return nullptr;
}

}  // namespace hil::harness
