#include "tools/FitMode.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace dpd {

void FitPrinter::row(const std::string& label, const std::string& a, const std::string& b) const {
    out_ << "    " << std::left << std::setw(22) << label;
    if (b.empty()) out_ << a;
    else out_ << std::setw(28) << a << b;
    out_ << std::right << "\n";
}

std::string FitPrinter::num(double x) {
    std::ostringstream os;
    os << std::setprecision(6) << x;
    return os.str();
}

}  // namespace dpd
