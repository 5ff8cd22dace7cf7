#pragma once
// When a bin's velocity and temperature are defined: the temperature is measured about a line
// fitted across the bin, which takes three particle-samples at least. Every tool that reads
// profiles drops the bins below this, and nothing else decides it.
namespace dpd {

inline constexpr double kMinParticleSamplesPerBin = 3.0;

// NaN counts are not usable.
inline bool usableBin(double particleSamples) { return particleSamples >= kMinParticleSamplesPerBin; }

}  // namespace dpd
