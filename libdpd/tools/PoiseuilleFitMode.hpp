#pragma once
// mode poiseuille: a parabola between two walls, driven by a uniform body force; nu and the slip
// length at each wall (analysis/PoiseuilleFit.hpp: fitPoiseuille).
#include "tools/FitMode.hpp"

namespace dpd {

class PoiseuilleFitMode : public FitMode {
public:
    std::string name() const override;
    void read(FitSlipLengthSetup& s) const override;
    void fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
             FitSlipLengthResult& r) const override;
    double measuredNu(const FitSlipLengthResult& r) const override;
    std::vector<double> jackknifed(const FitSlipLengthResult& r) const override;
    void setJackknifeErrors(FitSlipLengthResult& r, const std::vector<double>& errors) const override;
    double decayTime(const FitSlipLengthResult& r) const override;
    void write(Dictionary& d, const FitSlipLengthResult& r) const override;
    void print(const FitPrinter& out, const std::string& axis, const FitSlipLengthResult& r) const override;
};

}  // namespace dpd
