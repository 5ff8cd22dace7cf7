#pragma once
// mode reversePoiseuille: the two half-parabolas of a periodic box driven by +g and -g (no walls);
// the box along the gradient axis is the bins' range, so the bins must cover it (fitReversePoiseuille).
#include "tools/FitMode.hpp"

namespace dpd {

class ReversePoiseuilleFitMode : public FitMode {
public:
    std::string name() const override;
    void read(FitSlipLengthSetup& s) const override;
    void fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
             FitSlipLengthResult& r) const override;
    bool channel() const override { return false; }
    double measuredNu(const FitSlipLengthResult& r) const override;
    void write(Dictionary& d, const FitSlipLengthResult& r) const override;
    void print(const FitPrinter& out, const std::string& axis, const FitSlipLengthResult& r) const override;
};

}  // namespace dpd
