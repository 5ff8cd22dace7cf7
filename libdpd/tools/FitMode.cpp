#include "tools/FitMode.hpp"

#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace dpd {

void FitPrinter::row(const std::string& label, const std::string& a, const std::string& b) const {
    out_ << "    " << std::left << std::setw(22) << label;
    if (b.empty()) out_ << a;
    else out_ << std::setw(28) << a << b;
    out_ << std::right << "\n";
}

double FitMode::decayTime(const FitSlipLengthResult&) const { return std::numeric_limits<double>::quiet_NaN(); }

std::string FitPrinter::num(double x) {
    std::ostringstream os;
    os << std::setprecision(6) << x;
    return os.str();
}

}  // namespace dpd
