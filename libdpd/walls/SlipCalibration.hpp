#pragma once
// A slip-length calibration of the tunable-slip wall (docs/walls.md 3.7): for one fluid, one step and
// one wall model, the slip length b measured at several frictions gamma_L (from Couette and Poiseuille
// sweeps fitted by analysis/HydrodynamicWall), and where the wall acts: the hydrodynamic wall lies
// `wallOffset` inside the fluid from the plane the wall is put at. A wall that asks for a slip length
// takes its friction from the calibration of its own fluid and model, and its plane moved back by the
// offset, so that b is measured from where the user put the wall.
//
// A calibration holds only for what it was made with: the key names the fluid (density, a, gamma, kT,
// dimension, cutoff), the step (deltaT and the integrator with its coefficients) and the wall model
// (z_c, WCA epsilon and sigma, the friction's components, the fluid behind). A case finds the
// calibration whose key matches its own, or is refused with the entry that differs.
#include "walls/TunableSlipParameters.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;

struct SlipCalibrationKey {
    // The fluid.
    double density = 0.0, a = 0.0, gamma = 0.0, kT = 0.0, cutoff = 1.0;
    int dimension = 3;
    // The step: deltaT and the integrator as its dictionary says it ("GrootWarren lambda 0.65").
    double dt = 0.0;
    std::string integrator;
    // The wall model (gammaL aside, which the calibration sweeps).
    double zc = 0.0, epsilon = 0.0, sigma = 0.0, behindA = 0.0, behindDensity = 0.0;
    bool tangentialOnly = false;

    // The wall model of a tunable-slip wall's parameters (their gammaL is not part of it).
    void setWallModel(const TunableSlipParameters& wall);
    // The first entry, as "fluid/a 25 against 0", in which this key and `other` differ (numbers to a
    // relative 1e-9); empty when they match.
    std::string firstDifference(const SlipCalibrationKey& other) const;
    // The key's entries as a calibration file writes them: fluid { }, step { }, wall { }.
    void writeTo(Dictionary& d) const;
    static SlipCalibrationKey read(const Dictionary& d);
};

struct SlipCalibrationPoint {
    double gammaL = 0.0;
    double slipLength = 0.0, slipLengthError = 0.0;  // from the hydrodynamic wall
};

// The friction a wall takes for an asked slip length, with what the calibration says of it.
struct CalibratedFriction {
    double gammaL = 0.0;
    double slipLengthError = 0.0;  // the calibration's error at that b (interpolated)
    // How far behind where the user puts the wall its plane goes: the calibration's wallOffset, less
    // the shift of a b below the calibrated range (wallFor).
    double planeOffset = 0.0;
};

class SlipCalibration {
public:
    SlipCalibration(SlipCalibrationKey key, std::vector<SlipCalibrationPoint> points, double wallOffset,
                    double wallOffsetError, std::string source);

    const SlipCalibrationKey& key() const { return key_; }
    // In increasing gamma_L, so decreasing b.
    const std::vector<SlipCalibrationPoint>& points() const { return points_; }
    double wallOffset() const { return wallOffset_; }
    double wallOffsetError() const { return wallOffsetError_; }
    const std::string& source() const { return source_; }  // the file it was read from, or what made it
    double smallestSlip() const { return points_.back().slipLength; }
    double largestSlip() const { return points_.front().slipLength; }

    // The friction for slip length b: b is close to linear in 1/gamma_L (the prediction of
    // walls/TunableSlipParameters.hpp, 2 z_c / alpha at small alpha), so the two calibrated points
    // that bracket b are joined by a line in 1/gamma_L. Throws std::out_of_range naming the
    // calibrated range for b outside it.
    CalibratedFriction frictionFor(double b) const;
    // The wall for slip length b measured from where the user puts it, down to no slip (b 0): within
    // the calibrated range, frictionFor(b) with the plane wallOffset behind. Below it, the stiffest
    // calibrated friction, whose flow is that of a wall smallestSlip() - b further out: its plane goes
    // that much less far behind (the Navier condition at slip b_min is, for shear and Poiseuille flow
    // alike, the condition at slip b a distance b_min - b further from the fluid). Throws
    // std::out_of_range for b negative or above the range.
    CalibratedFriction wallFor(double b) const;

    // A calibration file: the key, wallOffset and wallOffsetError, and the lists gammaL, slipLength
    // and slipLengthError. InputError at the entry for a missing or bad one: fewer than two points,
    // lists of different lengths, a gammaL not positive, a b that does not fall as gamma_L rises.
    static SlipCalibration read(const Dictionary& d);
    void writeTo(Dictionary& d) const;

private:
    SlipCalibrationKey key_;
    std::vector<SlipCalibrationPoint> points_;
    double wallOffset_ = 0.0, wallOffsetError_ = 0.0;
    std::string source_;
};

// The calibration among `files` (read in turn; files that do not exist are passed over) whose key
// matches `key`. Throws std::runtime_error when none does, naming the files tried and, for each, the
// entry that differs.
SlipCalibration findSlipCalibration(const std::vector<std::string>& files, const SlipCalibrationKey& key);

// Where calibrations are looked for: the case's constant/slipCalibration, then every file of the
// user's cache directory ($DPD_SLIP_CALIBRATIONS, else $HOME/.cache/dpdFoamLike/slipCalibrations), in
// name order, then those the project ships ($DPD_PROJECT_DIR/etc/slipCalibrations, but its README).
std::vector<std::string> slipCalibrationFiles(const std::string& caseDir);

}  // namespace dpd
