#include "sampling/BinAccumulatorFile.hpp"

#include "core/Error.hpp"
#include "io/Hdf5File.hpp"

#include <filesystem>

namespace dpd {

void writeBins(const std::string& file, const BinAccumulator& acc, int dimension, double crossSection, double time,
               const std::vector<double>& sections) {
    std::filesystem::create_directories(std::filesystem::path(file).parent_path());
    const auto& blocks = acc.blocks();
    const int nBins = acc.layout().binCount();
    std::vector<double> flat;
    flat.reserve(blocks.size() * nBins * BinSums::kFields);
    for (const auto& block : blocks)
        for (const BinSums& b : block) flat.insert(flat.end(), b.s.begin(), b.s.end());
    std::vector<std::int64_t> perBlock(acc.samplesPerBlock().begin(), acc.samplesPerBlock().end());
    std::vector<std::int64_t> mask(acc.speciesMask().begin(), acc.speciesMask().end());
    Hdf5Writer w(file);
    w.writeDoubles("blocks", flat, {static_cast<hsize_t>(blocks.size()), static_cast<hsize_t>(nBins),
                                    static_cast<hsize_t>(BinSums::kFields)});
    w.writeInt64("samplesPerBlock", perBlock, {static_cast<hsize_t>(perBlock.size())});
    w.writeAttribute("/", "format", "dpdFoamLike-bins-2");
    w.writeAttribute("/", "stressFlowAxis", acc.stressFlowAxis());
    w.writeAttribute("/", "axis", acc.layout().axis);
    w.writeAttribute("/", "nBins", acc.layout().nBins);
    w.writeAttribute("/", "lo", acc.layout().lo);
    w.writeAttribute("/", "hi", acc.layout().hi);
    if (acc.layout().twoAxes()) {  // a 2-D grid of bins; 1-D files stay as they were
        w.writeAttribute("/", "axis2", acc.layout().axis2);
        w.writeAttribute("/", "nBins2", acc.layout().nBins2);
        w.writeAttribute("/", "lo2", acc.layout().lo2);
        w.writeAttribute("/", "hi2", acc.layout().hi2);
    }
    if (!sections.empty()) w.writeAttribute("/", "sections", sections);
    w.writeAttribute("/", "blockSamples", static_cast<std::int64_t>(acc.blockSamples()));
    w.writeAttribute("/", "dimension", dimension);
    w.writeAttribute("/", "crossSection", crossSection);
    w.writeAttribute("/", "time", time);
    w.writeAttribute("/", "speciesMask", mask);
    w.commit();
}

StoredBins readBins(const std::string& file) {
    Hdf5Reader r(file);
    // Format 1 had the 12 basic fields per bin and no stress; format 2 has all 21 and the stress axis.
    const std::string format = r.hasAttribute("/", "format") ? r.attributeString("/", "format") : "";
    if (format != "dpdFoamLike-bins-1" && format != "dpdFoamLike-bins-2")
        throw IoError(file + ": not a dpdFoamLike bins file (attribute 'format' missing or different)");
    const hsize_t fields = format == "dpdFoamLike-bins-1" ? BinSums::kBasicFields : BinSums::kFields;
    BinLayout layout;
    layout.axis = static_cast<int>(r.attributeInt("/", "axis"));
    layout.nBins = static_cast<int>(r.attributeInt("/", "nBins"));
    layout.lo = r.attributeDouble("/", "lo");
    layout.hi = r.attributeDouble("/", "hi");
    if (r.hasAttribute("/", "axis2")) {
        layout.axis2 = static_cast<int>(r.attributeInt("/", "axis2"));
        layout.nBins2 = static_cast<int>(r.attributeInt("/", "nBins2"));
        layout.lo2 = r.attributeDouble("/", "lo2");
        layout.hi2 = r.attributeDouble("/", "hi2");
    }
    std::vector<hsize_t> dims;
    const std::vector<double> flat = r.readDoubles("blocks", &dims);
    const std::vector<std::int64_t> perBlock = r.readInt64("samplesPerBlock");
    if (dims.size() != 3 || dims[1] != static_cast<hsize_t>(layout.binCount()) || dims[2] != fields ||
        perBlock.size() != dims[0])
        throw IoError(file + ": dataset 'blocks' does not have the shape (nBlocks, nBins, " + std::to_string(fields) + ")");
    std::vector<std::vector<BinSums>> blocks(dims[0], std::vector<BinSums>(layout.binCount()));
    std::size_t k = 0;
    for (auto& block : blocks)
        for (BinSums& b : block)
            for (hsize_t f = 0; f < fields; ++f) b.s[f] = flat[k++];
    std::vector<std::uint8_t> mask;
    for (auto m : r.attributeInts("/", "speciesMask")) mask.push_back(static_cast<std::uint8_t>(m));
    StoredBins out;
    out.accumulator = BinAccumulator::fromBlocks(layout, mask, r.attributeInt("/", "blockSamples"), std::move(blocks),
                                                 std::vector<long>(perBlock.begin(), perBlock.end()));
    if (format == "dpdFoamLike-bins-2")
        out.accumulator.setStressFlowAxis(static_cast<int>(r.attributeInt("/", "stressFlowAxis")));
    out.dimension = static_cast<int>(r.attributeInt("/", "dimension"));
    out.crossSection = r.attributeDouble("/", "crossSection");
    out.time = r.attributeDouble("/", "time");
    if (r.hasAttribute("/", "sections")) out.sections = r.attributeDoubles("/", "sections");
    return out;
}

}  // namespace dpd
