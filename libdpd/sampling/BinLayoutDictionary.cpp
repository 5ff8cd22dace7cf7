#include "sampling/BinLayoutDictionary.hpp"

#include "core/Axis.hpp"
#include "io/Dictionary.hpp"

namespace dpd {

namespace {

// An axis letter of a bin layout: one of the box's active axes.
int activeAxisFromLetter(const Dictionary& d, const std::string& key, const std::string& s, const Box& box) {
    const int axis = axisFromLetter(s);
    if (axis < 0) d.fail(key, "expected x, y or z, not '" + s + "'");
    if (!box.isActiveAxis(axis)) d.fail(key, "a 2-D scene lies in the x-z plane: there is no y axis");
    return axis;
}

BinLayout readOneAxis(const Dictionary& d, const Box& box) {
    BinLayout layout;
    layout.axis = activeAxisFromLetter(d, "axis", d.get<std::string>("axis"), box);
    layout.nBins = d.getPositive<int>("nBins");
    layout.lo = d.getOrDefault<double>("min", box.lo[layout.axis]);
    layout.hi = d.getOrDefault<double>("max", box.hi[layout.axis]);
    if (!(layout.hi > layout.lo)) d.fail(d.found("max") ? "max" : "min", "max must be greater than min");
    return layout;
}

// A pair of values for the two axes, or the box's range when the key is absent.
std::vector<double> pairOrBox(const Dictionary& d, const std::string& key, double first, double second) {
    if (!d.found(key)) return {first, second};
    const std::vector<double> v = d.get<std::vector<double>>(key);
    if (v.size() != 2) d.fail(key, "expected two values, one per axis of axes");
    return v;
}

BinLayout readTwoAxes(const Dictionary& d, const Box& box) {
    const std::vector<std::string> axes = d.get<std::vector<std::string>>("axes");
    if (axes.size() != 2) d.fail("axes", "expected two axes, e.g. (x z)");
    BinLayout layout;
    layout.axis = activeAxisFromLetter(d, "axes", axes[0], box);
    layout.axis2 = activeAxisFromLetter(d, "axes", axes[1], box);
    if (layout.axis == layout.axis2) d.fail("axes", "the two axes must differ");
    const std::vector<int> n = d.get<std::vector<int>>("nBins");
    if (n.size() != 2 || n[0] < 1 || n[1] < 1) d.fail("nBins", "expected two positive bin counts, one per axis");
    layout.nBins = n[0];
    layout.nBins2 = n[1];
    const std::vector<double> lo = pairOrBox(d, "min", box.lo[layout.axis], box.lo[layout.axis2]);
    const std::vector<double> hi = pairOrBox(d, "max", box.hi[layout.axis], box.hi[layout.axis2]);
    layout.lo = lo[0], layout.lo2 = lo[1], layout.hi = hi[0], layout.hi2 = hi[1];
    if (!(layout.hi > layout.lo) || !(layout.hi2 > layout.lo2))
        d.fail(d.found("max") ? "max" : "min", "max must be greater than min along both axes");
    return layout;
}

}  // namespace

std::vector<std::string> binLayoutKeys() { return {"axis", "axes", "nBins", "min", "max", "sections"}; }

BinLayout readBinLayout(const Dictionary& d, const Box& box) {
    if (d.found("axes") && d.found("axis")) d.fail("axes", "give either axis (1-D bins) or axes (a 2-D grid), not both");
    if (d.found("axes")) return readTwoAxes(d, box);
    if (d.found("sections")) d.fail("sections", "sections cut a 2-D grid of bins: give axes (a b) instead of axis");
    return readOneAxis(d, box);
}

std::vector<double> readSections(const Dictionary& d, const BinLayout& layout) {
    if (!d.found("sections")) return {};
    const std::vector<double> s = d.get<std::vector<double>>("sections");
    for (const double x : s)
        if (x < layout.lo || x >= layout.hi)
            d.fail("sections", "position " + std::to_string(x) + " lies outside the bins along " + axisLetter(layout.axis));
    return s;
}

double binCrossSection(const BinLayout& layout, const Box& box) {
    double across = box.volume() / box.length()[layout.axis];
    if (layout.twoAxes()) across /= box.length()[layout.axis2];
    return across;
}

}  // namespace dpd
