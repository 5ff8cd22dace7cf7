#pragma once
// A fit mode of fitSlipLength (mode poiseuille | reversePoiseuille | couette in fitSlipLengthDict):
// each reads and checks its own part of the dictionary against the model, fits a profile, and
// writes and prints its results. Adding a mode adds its files and one line in FitModes.cpp.
#include "analysis/PoiseuilleFit.hpp"
#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "sampling/ProfileTable.hpp"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

struct FitSlipLengthSetup;
struct FitSlipLengthResult;

// Rows of the printed result: a label and one or two columns.
class FitPrinter {
public:
    explicit FitPrinter(std::ostream& out) : out_(out) {}
    void row(const std::string& label, const std::string& a, const std::string& b = "") const;
    static std::string num(double x);
    static std::string withErr(double v, double e) { return num(v) + " +- " + num(e); }

private:
    std::ostream& out_;
};

// What a mode fits: the table's usable points (with their blocks, when the sampling file is known)
// and, per kept block, the shear stress of every table row (empty without blocks or stress).
struct FitPoints {
    Profile1D profile;
    std::vector<std::vector<double>> stressBlocks;
};

class FitMode {
public:
    virtual ~FitMode() = default;
    virtual std::string name() const = 0;
    // Checks the dictionary's mode-specific keys against the model and sets the component, exclude
    // and fit range of the setup (InputError naming the file, line and keyword).
    virtual void read(FitSlipLengthSetup& s) const = 0;
    // Fits one table's usable points.
    virtual void fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
                     FitSlipLengthResult& r) const = 0;
    // Whether the profile lies between two walls (then tunable-slip walls get a predicted slip length).
    virtual bool channel() const { return true; }
    // The viscosity the fit measured; NaN when it measures none.
    virtual double measuredNu(const FitSlipLengthResult& r) const = 0;
    // The quantities a jackknife over super-blocks gives errors for, and setting those errors (a mode
    // returning none refuses superBlocks), and the profile's slowest decay time (NaN: unknown).
    virtual std::vector<double> jackknifed(const FitSlipLengthResult&) const { return {}; }
    virtual void setJackknifeErrors(FitSlipLengthResult&, const std::vector<double>&) const {}
    virtual double decayTime(const FitSlipLengthResult&) const;
    virtual void write(Dictionary& d, const FitSlipLengthResult& r) const = 0;
    virtual void print(const FitPrinter& out, const std::string& axis, const FitSlipLengthResult& r) const = 0;
};

using FitModeRegistry = Registry<FitMode>;
const FitModeRegistry& fitModes();

}  // namespace dpd
