#pragma once
// mode couette: a line over the central part between two sliding walls (no body force); slip at each
// wall, and nu = <sigma> / (shear rate rho) when the table has the shear stress (CouetteFit.hpp).
#include "tools/FitMode.hpp"

namespace dpd {

class CouetteFitMode : public FitMode {
public:
    std::string name() const override;
    void read(FitSlipLengthSetup& s) const override;
    void fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
             FitSlipLengthResult& r) const override;
    double measuredNu(const FitSlipLengthResult& r) const override;
    void write(Dictionary& d, const FitSlipLengthResult& r) const override;
    void print(const FitPrinter& out, const std::string& axis, const FitSlipLengthResult& r) const override;
};

}  // namespace dpd
