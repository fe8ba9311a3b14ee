/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CoilWinding.h
 * Where each point z in [0, L] of the fibre lies in the coil (which thermal-node layer and
 * sector), for helical, dipolar, quadrupolar and octupolar windings, and the Shupe rate error
 * that follows from the node temperature rates (seed eq. 1; Shupe, Appl. Opt. 19(5):654, 1980):
 *
 *   Omega_E = n / (L D) * (dn/dT + n alpha) * Integral_0^L Tdot(z) (2 z - L) dz   [rad/s]
 *
 * Since every node has one temperature, the integral is sum_k w_k Tdot_k with the node weights
 * w_k = integral of (2 z - L) over the fibre inside node k [m^2], computed once.
 *
 * Winding: the coil has `fiber_layers` physical layers (many more than the thermal node
 * layers; physical layer l lies in node layer floor(l * node_layers / fiber_layers)); each layer
 * holds L / fiber_layers of fibre, turning around the coil (one turn = pi D). Symmetric windings
 * start at the fibre point z_m = L/2 + midpoint_offset_m and wind the two halves (A: towards
 * z = 0, B: towards z = L) in the layer order of the pattern (dipolar AB, quadrupolar ABBA,
 * octupolar ABBABAAB); when a half runs out, the other fills the remaining layers. The
 * midpoint offset (a length asymmetry between the halves, in metres) is the imperfection that
 * sets the residual Shupe error of a symmetric winding: with 0 the residual comes only from the
 * pattern's own imperfect pairing. A second imperfection, `layer_length_mismatch` = e (default
 * 0): every layer of half A holds L / fiber_layers x (1 + e) of fibre and every layer of half B
 * x (1 - e) (the two supply spools wound at different tension or pitch: a turn-count asymmetry
 * between paired layers), so the pairing drifts layer after layer; the last layer takes what is
 * left. Helical: layer after layer from z = 0 (e unused). */

#include <Eigen/Dense>

#include <string>

namespace mrpt_fog::sim
{
enum class WindingPattern
{
	Helical,
	Dipolar,
	Quadrupolar,
	Octupolar
};

/** "helical" / "dipolar" / "quadrupolar" / "octupolar". */
const char* toString(WindingPattern p);
/** Parses the names above; throws std::invalid_argument. */
WindingPattern windingPatternFromString(const std::string& s);

/** Optical and winding parameters of the coil. */
struct WindingParams
{
	WindingPattern pattern = WindingPattern::Quadrupolar;
	double fiber_length_m = 1500.0;  //!< seed coil
	double mean_diameter_m = 0.1;  //!< seed-class coil (PHYSICS.md)
	int fiber_layers = 48;  //!< physical layers (estimate: 10 mm / ~0.2 mm pitch)
	double midpoint_offset_m = 0.0;  //!< length asymmetry of the two halves [m]
	/** Relative fibre-length difference of the two halves' layers (see the file comment); |e| < 0.5. */
	double layer_length_mismatch = 0.0;
	double refractive_index = 1.46;  //!< n (PHYSICS.md)
	double dn_dT_per_K = 1.0e-5;  //!< thermo-optic coefficient (PHYSICS.md)
	double expansion_per_K = 5.5e-7;  //!< silica expansion alpha (PHYSICS.md)

	/** Throws std::invalid_argument naming the first bad field. */
	void validate() const;
};

class CoilWinding
{
   public:
	/** Maps the fibre onto node_layers x sectors thermal nodes (node index = layer * sectors +
	 * sector, sector j centred at 360 j / sectors deg). Throws on bad parameters. */
	CoilWinding(const WindingParams& params, int node_layers, int sectors);

	const WindingParams& params() const { return p_; }
	/** w_k = integral of (2 z - L) dz over the fibre in node k [m^2]. */
	const Eigen::VectorXd& nodeWeights_m2() const { return w_; }
	/** Fibre length in each node [m] (sums to L). */
	const Eigen::VectorXd& nodeFiberLength_m() const { return len_; }
	/** n (dn/dT + n alpha) / (L D) [1/(K m^2)]: multiplies sum_k w_k Tdot_k to give rad/s. */
	double shupeGain() const;
	/** Shupe rate error [rad/s] for the node temperature rates Tdot [K/s] (coil nodes first;
	 * extra entries are ignored). */
	double shupeRate_rad_s(const Eigen::VectorXd& Tdot_K_s) const;

   private:
	WindingParams p_;
	int node_layers_, sectors_;
	Eigen::VectorXd w_, len_;
};

}  // namespace mrpt_fog::sim
