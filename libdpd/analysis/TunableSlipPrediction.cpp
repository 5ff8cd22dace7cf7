#include "analysis/TunableSlipPrediction.hpp"

#include "io/Dictionary.hpp"
#include "walls/PlanarWallSettings.hpp"

#include <sstream>
#include <vector>

namespace dpd {

TunableSlipPrediction predictTunableSlip(const PlanarWallSettings& lower, const PlanarWallSettings& upper, double density, double nu,
                                         const std::string& nuSource) {
    TunableSlipPrediction p;
    const PlanarWallSettings* walls[2] = {&lower, &upper};
    for (int k = 0; k < 2; ++k) p.tunable[k] = walls[k]->hasTunableSlip;
    p.any = p.tunable[0] || p.tunable[1];
    if (!p.any) return p;
    p.density = density;
    p.nu = nu;
    p.nuSource = nuSource;
    for (int k = 0; k < 2; ++k) {
        if (!p.tunable[k]) continue;
        const TunableSlipParameters& t = walls[k]->tunableSlip;
        p.alpha[k] = tunableSlipAlpha(t.gammaL, t.zc, density, density * nu);
        p.slipLength[k] = predictedTunableSlipLength(t.gammaL, t.zc, density, density * nu);
    }
    return p;
}

namespace {

// (lower upper) as numbers, or as words with "none" for a wall that has no tunable slip.
void setWallPair(Dictionary& d, const std::string& key, const TunableSlipPrediction& p, const double (&value)[2]) {
    if (p.tunable[0] && p.tunable[1]) {
        d.setValue(key, std::vector<double>{value[0], value[1]});
        return;
    }
    std::vector<std::string> words;
    for (int k = 0; k < 2; ++k) {
        std::ostringstream os;
        os.precision(17);
        os << value[k];
        words.push_back(p.tunable[k] ? os.str() : "none");
    }
    d.setValue(key, words);
}

}  // namespace

void writeTunableSlipPrediction(Dictionary& d, const TunableSlipPrediction& p) {
    if (!p.any) return;
    setWallPair(d, "slipLengthPredicted", p, p.slipLength);
    setWallPair(d, "slipPredictionAlpha", p, p.alpha);
    d.setValue("slipPredictionNu", p.nu);
    d.setValue("slipPredictionNuSource", p.nuSource);
    d.setValue("slipPredictionDensity", p.density);
}

}  // namespace dpd
