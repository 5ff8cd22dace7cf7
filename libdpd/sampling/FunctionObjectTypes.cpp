// The function object types controlDict's `functions` can name: one line per type.
#include "sampling/BinnedProfile.hpp"
#include "sampling/ChainStatistics.hpp"

namespace dpd {

const FunctionObjectRegistry& functionObjectTypes() {
    static const FunctionObjectRegistry types = [] {
        FunctionObjectRegistry r;
        r.add("binnedProfile", &BinnedProfile::New);
        r.add("chainStatistics", &ChainStatistics::New);
        return r;
    }();
    return types;
}

}  // namespace dpd
