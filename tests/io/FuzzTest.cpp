// Garbage in, a clear error out: the dictionary reader (with the case readers behind it) and the
// snapshot reader (files cut short, numbers damaged, random bytes) are fed mutated and random input
// for a bounded time. Each input must either be read
// or be refused with the project's own error (InputError, IoError); any other exception, a crash or a
// hang fails the test. The generator is seeded, so a failure names an input that reproduces.
#include "case/ControlDict.hpp"
#include "case/DpdProperties.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace dpd;

namespace {

// Inputs per reader, and a wall-clock bound on each loop (CI runs the suite on two cores).
constexpr int kCases = 20000;
constexpr double kSecondsPerLoop = 20.0;

const char* const kDpdProperties = R"(FoamFile { version 2.0; format ascii; class dictionary; object dpdProperties; }
dimension 3;
kT 1;
cutoff 1;
seed 12345;
species { fluid { frozen no; } wall { frozen yes; } }
pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }
integrator { type GrootWarren; lambda 0.65; }
bodyForce { type uniform; value (0.02 0 0); }
walls
{
    lower { type plane; point (0 0 -5); normal (0 0 1); reflection bounceLayer; alpha 0.1; }
    upper { type plane; point (0 0 5); normal (0 0 -1); tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; } }
}
stability { maxKTRatio 2; maxInsideWalls 0; checkInterval 100; }
)";

const char* const kControlDict = R"(FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom latestTime;
startTime 0;
endTime 10;
deltaT 0.02;
writeControl runTime;
writeInterval $deltaT;
reportInterval 100;
functions
{
    channelProfile { type binnedProfile; axis z; nBins 40; sampleInterval 10; fields (velocity density kT); }
}
)";

// Pieces that stress a reader: huge and odd numbers, unbalanced brackets, directives, macros.
const std::vector<std::string> kPieces = {
    "1e999999", "-1e-999999", "99999999999999999999999", "-0", "nan", "inf", "0x1p3", "1e30", "((((((", "))",
    "{", "}", ";", "$", "$kT", "$walls.lower.point", "#include", "#include \"\"", "#includeIfPresent \"nowhere\"",
    "\"", "//", "/*", "*/", "\\", "\n", "(1 2)", "3(1 2 3)", "2(1 2 3)", "yes", "type", "walls", "{ a 1; }",
    std::string(1, '\0'), "\xff\xfe", "a-b", "$FoamFile", "#remove", "(0 0 1e308)"};

std::string mutate(const std::string& text, std::mt19937_64& rng) {
    std::string s = text;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
        const std::size_t at = s.empty() ? 0 : rng() % (s.size() + 1);
        switch (rng() % 5) {
            case 0: s.resize(at); break;                                                  // truncate
            case 1: if (at < s.size()) s[at] = static_cast<char>(rng() % 256); break;     // any byte
            case 2: s.insert(at, kPieces[rng() % kPieces.size()]); break;                 // a hard piece
            case 3: if (at < s.size()) s.erase(at, 1 + rng() % 8); break;                 // a gap
            default: {                                                                    // a repeated line
                const std::size_t from = s.rfind('\n', at);
                const std::size_t to = s.find('\n', at);
                if (from != std::string::npos && to != std::string::npos) s.insert(to, s.substr(from, to - from));
            }
        }
    }
    return s;
}

std::string randomBytes(std::mt19937_64& rng) {
    std::string s(rng() % 400, ' ');
    for (char& c : s) c = static_cast<char>(rng() % 256);
    return s;
}

// Reads text as a dictionary and through every case reader that takes one; only the project's errors
// may come out.
void readEverything(const std::string& text) {
    try {
        const Dictionary d = Dictionary::parse(text, "fuzz");
        for (const std::string& key : d.keys()) {
            if (d.isDict(key)) continue;
            try { d.get<double>(key); } catch (const InputError&) {}
            try { d.get<Eigen::Vector3d>(key); } catch (const InputError&) {}
            try { d.get<std::vector<std::vector<double>>>(key); } catch (const InputError&) {}
            try { d.get<long>(key); } catch (const InputError&) {}
        }
        try { readDpdModel(d); } catch (const InputError&) {}
        try { readRunControl(d); } catch (const InputError&) {}
    } catch (const InputError&) {
    }
}

// Runs `one` on inputs until kCases are done or the time is up; an unexpected exception fails the
// test with the input's number.
template <class One>
int fuzzLoop(One&& one) {
    const auto start = std::chrono::steady_clock::now();
    int k = 0;
    for (; k < kCases; ++k) {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > kSecondsPerLoop) break;
        try {
            one(k);
        } catch (const std::exception& e) {
            ADD_FAILURE() << "input " << k << ": " << typeid(e).name() << ": " << e.what();
            return k;
        }
    }
    return k;
}

// Where in the file the particle datasets keep their values (offset, bytes): damage there is damage
// to numbers. Damage to HDF5's own metadata is left out: libhdf5 1.10 itself can crash on it (a
// corrupted global heap under a string attribute segfaults in H5HG_read), which no reader built on it
// can catch in-process.
std::vector<std::pair<std::size_t, std::size_t>> rawDataRegions(const fs::path& file) {
    std::vector<std::pair<std::size_t, std::size_t>> regions;
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    for (const char* name : {"particles/position", "particles/velocity", "particles/force", "particles/id",
                             "particles/species"}) {
        const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
        const haddr_t offset = H5Dget_offset(d);
        const hsize_t size = H5Dget_storage_size(d);
        if (offset != HADDR_UNDEF && size > 0) regions.emplace_back(offset, size);
        H5Dclose(d);
    }
    H5Fclose(f);
    return regions;
}

std::string readBinary(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(Fuzz, DictionaryReadersRefuseGarbageWithTheirOwnErrors) {
    std::mt19937_64 rng(20261124);
    const std::vector<std::string> seeds = {kDpdProperties, kControlDict};
    const int done = fuzzLoop([&](int k) {
        const std::string text = k % 10 == 9 ? randomBytes(rng) : mutate(seeds[k % seeds.size()], rng);
        readEverything(text);
    });
    EXPECT_GE(done, 500) << "too few inputs in the time";
    // The unmutated seeds read cleanly (else every mutant would be refused for the seed's own fault).
    EXPECT_NO_THROW(readDpdModel(Dictionary::parse(kDpdProperties, "seed")));
    EXPECT_NO_THROW(readRunControl(Dictionary::parse(kControlDict, "seed")));
}

TEST(Fuzz, SnapshotReaderRefusesDamagedFilesWithIoError) {
    const fs::path dir = fs::temp_directory_path() / ("dpdFuzz-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    Snapshot s;
    s.box.hi = Eigen::Vector3d(4, 4, 4);
    s.speciesNames = {"fluid", "wall"};
    s.speciesFrozen = {false, true};
    for (int i = 0; i < 64; ++i) s.particles.add(i, i % 2, 0.06 * i, 0.05 * i, 0.04 * i, 0.1, -0.2, 0.3);
    writeSnapshot((dir / "0").string(), s);
    const std::string good = readBinary(dir / "0/particles.h5");
    ASSERT_NO_THROW(readSnapshot((dir / "0/particles.h5").string()));
    const std::vector<std::pair<std::size_t, std::size_t>> dataRegions = rawDataRegions(dir / "0/particles.h5");
    ASSERT_EQ(dataRegions.size(), 5u);
    std::mt19937_64 rng(7);
    const fs::path damaged = dir / "damaged.h5";
    const int done = fuzzLoop([&](int k) {
        std::string bytes = good;
        if (k % 3 == 0) {
            bytes.resize(rng() % good.size());  // a write cut short
        } else if (k % 3 == 1) {
            for (int e = 0; e < 1 + static_cast<int>(rng() % 4); ++e) {
                const auto& [offset, size] = dataRegions[rng() % dataRegions.size()];
                bytes[offset + rng() % size] = static_cast<char>(rng() % 256);
            }
        } else {
            bytes = randomBytes(rng);
        }
        std::ofstream(damaged, std::ios::binary | std::ios::trunc) << bytes;
        try {
            readSnapshot(damaged.string());
        } catch (const IoError&) {
        }
    });
    EXPECT_GE(done, 300) << "too few inputs in the time";
    fs::remove_all(dir);
}
