// Must NOT compile (test scenario_key_missing_does_not_compile): a reader naming a key that its
// section's table does not list is refused by KeyIn's compile-time lookup (scenario_keys.h).
#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness {

inline constexpr ScenarioKey kTable[] = {
    {"listed_m", KeyType::kNumber, "m", "0", 0, 1, "a key of the table"},
};

double ReadsAKeyTheTableLacks(const YamlReader& y) {
  const KeyedReader<kTable> r(y);
#ifdef HIL_KEY_LISTED
  return r.Number("listed_m", 0);  // the control: a listed key compiles
#else
  return r.Number("unlisted_m", 0);
#endif
}

}  // namespace hil::harness
