#include "tools/ChainScalingTool.hpp"

#include "core/Error.hpp"
#include "io/TimeDirectories.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <regex>
#include <set>
#include <stdexcept>

namespace dpd {

namespace fs = std::filesystem;

namespace {

// The latest postProcessing/<function>/<time>/chainStatistics.dat of a case.
std::string latestTable(const std::string& dir, const std::string& function) {
    const fs::path root = fs::path(dir) / "postProcessing" / function;
    const std::vector<TimeDirectory> times = fs::is_directory(root) ? listTimes(root.string()) : std::vector<TimeDirectory>{};
    if (times.empty()) throw IoError(root.string() + ": no time directory (run the case with its " + function + " function object)");
    const fs::path table = root / times.back().name / "chainStatistics.dat";
    if (!fs::exists(table)) throw IoError(table.string() + ": not found");
    return table.string();
}

// The "# mean <name> <value> +- <error>" line of a chainStatistics table.
std::pair<double, double> headerMean(const std::string& table, const std::string& text, const std::string& name) {
    const std::regex line("# mean " + name + "\\s+(\\S+) \\+- (\\S+)");
    std::smatch m;
    if (!std::regex_search(text, m, line)) throw IoError(table + ": no '# mean " + name + "' line (not a chainStatistics table?)");
    try {
        return {std::stod(m[1].str()), std::stod(m[2].str())};
    } catch (const std::exception&) {
        throw IoError(table + ": the mean of " + name + " is not a number: " + m[0].str());
    }
}

}  // namespace

ChainScalingCase readChainScalingCase(const std::string& dir, const std::string& function) {
    ChainScalingCase c;
    c.dir = dir;
    const Dictionary chains = Dictionary::readFile((fs::path(dir) / "system" / "insertChainsDict").string());
    c.length = chains.getPositive<int>("length");
    const std::string table = latestTable(dir, function);
    std::ifstream in(table);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::tie(c.rg2, c.rg2Error) = headerMean(table, text, "Rg2");
    std::tie(c.ree2, c.ree2Error) = headerMean(table, text, "Ree2");
    return c;
}

ChainScalingResult chainScaling(const std::vector<std::string>& dirs, const std::string& function) {
    ChainScalingResult r;
    for (const std::string& d : dirs) r.cases.push_back(readChainScalingCase(d, function));
    std::sort(r.cases.begin(), r.cases.end(), [](const auto& a, const auto& b) { return a.length < b.length; });
    std::set<int> lengths;
    std::vector<double> n, rg2, err;
    for (const ChainScalingCase& c : r.cases) {
        lengths.insert(c.length);
        n.push_back(c.length);
        rg2.push_back(c.rg2);
        err.push_back(c.rg2Error);
    }
    if (lengths.size() < 3)
        throw std::invalid_argument("chainScaling needs cases of at least 3 chain lengths, got " + std::to_string(lengths.size()));
    try {
        r.fit = fitPowerLaw(n, rg2, err);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("no fit of R_g^2 against N: ") + e.what() +
                                    " (a mean or its error is zero or negative: sample longer)");
    }
    return r;
}

Dictionary chainScalingDictionary(const ChainScalingResult& r) {
    Dictionary d;
    d.setValue("nu", r.nu());
    d.setValue("nuError", r.nuError());
    d.setValue("chi2PerDof", r.fit.chi2PerDof);
    d.setValue("dof", r.fit.dof);
    d.setValue("logAmplitude", r.fit.logAmplitude);
    std::vector<double> n, rg2, rg2e, ree2, ree2e;
    for (const ChainScalingCase& c : r.cases) {
        n.push_back(c.length);
        rg2.push_back(c.rg2);
        rg2e.push_back(c.rg2Error);
        ree2.push_back(c.ree2);
        ree2e.push_back(c.ree2Error);
    }
    d.setValue("length", n);
    d.setValue("Rg2", rg2);
    d.setValue("Rg2Error", rg2e);
    d.setValue("Ree2", ree2);
    d.setValue("Ree2Error", ree2e);
    return d;
}

void printChainScaling(std::ostream& out, const ChainScalingResult& r) {
    out << "    N      <R_g^2>                 <R_ee^2>                case\n";
    for (const ChainScalingCase& c : r.cases)
        out << "    " << std::left << std::setw(6) << c.length << std::setw(24)
            << (std::to_string(c.rg2) + " +- " + std::to_string(c.rg2Error)) << std::setw(24)
            << (std::to_string(c.ree2) + " +- " + std::to_string(c.ree2Error)) << c.dir << std::right << "\n";
    out << "    nu = " << r.nu() << " +- " << r.nuError() << "  (R_g^2 ~ N^(2 nu); chi2/dof " << r.fit.chi2PerDof
        << ", dof " << r.fit.dof << ")\n";
}

}  // namespace dpd
