// The fit modes fitSlipLengthDict can name: one line per mode.
#include "tools/CouetteFitMode.hpp"
#include "tools/PoiseuilleFitMode.hpp"
#include "tools/ReversePoiseuilleFitMode.hpp"

namespace dpd {

const FitModeRegistry& fitModes() {
    static const FitModeRegistry modes = [] {
        FitModeRegistry r;
        r.add("poiseuille", [] { return std::make_unique<PoiseuilleFitMode>(); });
        r.add("reversePoiseuille", [] { return std::make_unique<ReversePoiseuilleFitMode>(); });
        r.add("couette", [] { return std::make_unique<CouetteFitMode>(); });
        return r;
    }();
    return modes;
}

}  // namespace dpd
