#include "tools/CompareFVMOutput.hpp"

#include "core/Axis.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace dpd {

namespace {

void putDarcy(Dictionary& d, const CompareFVMResult& r) {
    d.setValue("porosityDPD", r.darcyDPD.porosity);
    d.setValue("porosityFVM", r.darcyFVM.porosity);
    d.setValue("superficialVelocityDPD", r.darcyDPD.superficialVelocity);
    d.setValue("superficialVelocityDPDErr", r.darcyDPD.superficialVelocityErr);
    d.setValue("superficialVelocityFVM", r.darcyFVM.superficialVelocity);
    d.setValue("permeabilityDPD", r.darcyDPD.permeability);
    d.setValue("permeabilityDPDErr", r.darcyDPD.permeabilityErr);
    d.setValue("permeabilityFVM", r.darcyFVM.permeability);
    d.setValue("permeabilityRatio", r.darcyDPD.permeability / r.darcyFVM.permeability);
}

void putMetrics(Dictionary& d, const ComparisonMetrics& m) {
    d.setValue("points", m.points);
    d.setValue("L2", m.L2);
    d.setValue("Linf", m.Linf);
    d.setValue("noiseL2", m.noiseL2);
    d.setValue("meanVelocityDPD", m.meanDPD);
    d.setValue("meanVelocityFVM", m.meanFVM);
    d.setValue("meanVelocityRatio", m.meanVelocityRatio);
}

}  // namespace

Dictionary compareFVMDictionary(const CompareFVMResult& r) {
    Dictionary d;
    d.setValue("time", r.time);
    d.setValue("profile", r.profileFile);
    d.setValue("foamCase", r.foamCase);
    d.setValue("foamTime", r.foamTime);
    d.setValue("axis", std::string(axisLetter(r.axis)));
    d.setValue("component", std::string(axisLetter(r.component)));
    putMetrics(d, r.field);
    if (r.hasDarcy) putDarcy(d, r);
    Dictionary& lines = d.subDictOrCreate("lines");
    for (const auto& [name, m] : r.lines) putMetrics(lines.subDictOrCreate(name), m);
    return d;
}

std::string compareFVMProfilesText(const CompareFVMResult& r) {
    std::ostringstream os;
    os << std::setprecision(17) << "# " << axisLetter(r.axis) << (r.axis2 >= 0 ? std::string(" ") + axisLetter(r.axis2) : "")
       << " uDPD uDPDErr uFVM";
    for (const auto& [name, u] : r.uLines) os << " u_" << name;
    os << "\n";
    for (std::size_t i = 0; i < r.x.size(); ++i) {
        os << r.x[i] << " ";
        if (r.axis2 >= 0) os << r.x2[i] << " ";
        os << r.uDPD[i] << " " << r.uDPDErr[i] << " " << r.uFVM[i];
        for (const auto& [name, u] : r.uLines) os << " " << u[i];
        os << "\n";
    }
    return os.str();
}

void printCompareFVM(std::ostream& out, const CompareFVMResult& r) {
    const auto row = [&](const std::string& label, const ComparisonMetrics& m) {
        out << "    " << std::left << std::setw(18) << label << std::right << std::setprecision(5) << "L2 " << std::setw(11)
            << m.L2 << "  Linf " << std::setw(11) << m.Linf << "  mean ratio " << std::setw(9) << m.meanVelocityRatio
            << "  (noise L2 " << m.noiseL2 << ", " << m.points << " points)\n";
    };
    out << "Time = " << r.time << ": " << r.profileFile << " against " << r.foamCase << " at " << r.foamTime << ", u"
        << axisLetter(r.component) << (r.axis2 >= 0 ? " on the grid " : " across ") << axisLetter(r.axis)
        << (r.axis2 >= 0 ? std::string(" ") + axisLetter(r.axis2) : "") << "\n";
    row("field", r.field);
    if (r.hasDarcy)
        out << "    Darcy              porosity DPD " << r.darcyDPD.porosity << " FVM " << r.darcyFVM.porosity
            << "  permeability DPD " << r.darcyDPD.permeability << " +- " << r.darcyDPD.permeabilityErr << " FVM "
            << r.darcyFVM.permeability << "  ratio " << r.darcyDPD.permeability / r.darcyFVM.permeability << "\n";
    for (const auto& [name, m] : r.lines) row("line " + name, m);
    for (const auto& name : r.skippedLines) out << "    line " << name << ": not along " << axisLetter(r.axis) << ", skipped\n";
}

}  // namespace dpd
