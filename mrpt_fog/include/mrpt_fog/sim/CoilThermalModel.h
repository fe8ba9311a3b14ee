/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CoilThermalModel.h
 * Lumped thermal network of a FOG coil in its housing:
 *  - the potted winding as `layers` radial layers (0 = inner, layers-1 = outer) x `sectors`
 *    angular sectors (sector j centred at 360 j / sectors deg), conduction radially and around;
 *  - an inner hub bonded to the inner layer;
 *  - the outer housing (air gap to the outer layer, a weak path to every winding node through
 *    the end faces, convection to chamber air);
 *  - a mount plate on one side (angle 0): bolted to the housing, to the hub, to the fixture
 *    (chamber air) and touching the coil flank near 0 deg;
 *  - the electronics board (heat source when powered) near 180 deg, on the housing, with a weak
 *    air path to the outer layer there.
 * Inputs: chamber air temperature [degC] and electronics power [W].
 *
 * The network C dT/dt = -K T + b_air T_air + e_el P is solved EXACTLY for inputs that vary
 * linearly over a step (first-order hold), through the modal decomposition of the symmetric
 * matrix C^-1/2 K C^-1/2: unconditionally stable at any time step, and the time constants are
 * the inverse eigenvalues (timeConstants_s()).
 *
 * Parameter values, each marked as sourced or estimated, are in CoilThermalParams. */

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace mrpt_fog::sim
{
/** Physical parameters of the coil's thermal network (SI units in the names). */
struct CoilThermalParams
{
	int layers = 8;  //!< radial node layers (>= 2)
	int sectors = 8;  //!< angular node sectors (>= 4)

	// Winding geometry: 1500 m of 165 um fibre (the length is the seed's), mean D 0.1 m (an
	// estimate: PHYSICS.md's example calculation; the seed gives no diameter) -> ~60 cm3 of potted
	// winding. Cross-section chosen 10 mm radial x 19 mm axial (estimate).
	double mean_diameter_m = 0.1;  //!< estimate (PHYSICS.md's example; not from the seed)
	double radial_thickness_m = 0.010;  //!< estimate (PHYSICS.md: "~1 cm potted winding")
	double axial_height_m = 0.019;  //!< estimate (winding volume / circumference / thickness)
	/** Volumetric heat capacity of silica + epoxy [J/(m3 K)] (estimate: rho ~2000, cp ~800). */
	double volumetric_heat_capacity_J_m3K = 1.6e6;
	/** Radial conductivity of a potted winding [W/(m K)] (estimate; with the heat capacity
	 * gives kappa ~1.6e-7 m2/s, PHYSICS.md ~1.5e-7). */
	double radial_conductivity_W_mK = 0.25;
	/** Tangential conductivity [W/(m K)] (estimate: along the silica fibre, higher). */
	double tangential_conductivity_W_mK = 0.6;

	// The seed's coil is FRAMELESS: no spool; the "hub" is the central post and the air of the
	// inner cavity, coupled to the inner surface only through a ~5 mm air gap, while the outer
	// surface sits ~0.5 mm from the housing wall. Heat therefore enters mainly from outside,
	// which gives the marked inner/outer differences of the seed's Fig. 2.
	double hub_capacity_J_K = 30.0;  //!< light central post + cavity air (estimate)
	/** Inner surface to the central post across the ~5 mm inner cavity (physical estimate,
	 * arithmetic in docs/reference/simulator.md): conduction through air k A / d = 0.026 W/(m K) x 5.4e-3 m2 /
	 * 5e-3 m = 0.028 W/K, plus radiation 4 eps_eff sigma T^3 A = 4 x 0.82 x 5.67e-8 x 298^3 x
	 * 5.4e-3 = 0.027 W/K (eps_eff 0.82 for two emissivity-0.9 surfaces), together 0.055 W/K
	 * (A = pi x 0.09 m x 0.019 m, the inner winding surface): conduction and radiation
	 * together, not a fitted value. */
	double hub_to_inner_W_K = 0.055;

	double housing_capacity_J_K = 900.0;  //!< 1 kg aluminium housing (PHYSICS.md)
	double housing_to_air_W_K = 0.5;  //!< convection hA (PHYSICS.md: ~0.5 W/K -> ~30 min)
	/** Outer surface to housing wall across a ~0.5 mm air gap (estimate: 0.026 / 5e-4 x 6.6e-3 m2
	 * = 0.34 W/K). */
	double outer_to_housing_W_K = 0.3;
	double faces_to_housing_W_K = 0.02;  //!< end faces to housing air, all nodes (estimate)

	double mount_capacity_J_K = 270.0;  //!< 0.3 kg aluminium plate (estimate)
	double mount_to_air_W_K = 0.3;  //!< to the chamber fixture (estimate)
	double mount_to_housing_W_K = 1.0;  //!< bolted joint (estimate)
	double mount_to_hub_W_K = 0.3;  //!< central post (estimate)
	double mount_to_coil_W_K = 0.02;  //!< coil flank touching the mount near 0 deg (estimate)

	double electronics_capacity_J_K = 60.0;  //!< board + components (estimate)
	double electronics_to_housing_W_K = 0.4;  //!< standoffs (estimate)
	double electronics_to_coil_W_K = 0.03;  //!< air path to the outer layer near 180 deg (estimate)
	double electronics_power_W = 2.5;  //!< FOG electronics + source, typical 2-5 W (estimate)

	/** Multiplies every heat capacity (coil, hub, housing, mount, electronics) by `factor`:
	 * every thermal time constant scales by it, the steady state does not change. */
	void scaleHeatCapacities(double factor)
	{
		volumetric_heat_capacity_J_m3K *= factor;
		hub_capacity_J_K *= factor;
		housing_capacity_J_K *= factor;
		mount_capacity_J_K *= factor;
		electronics_capacity_J_K *= factor;
	}

	/** Throws std::invalid_argument naming the first bad field (non-positive, too few nodes). */
	void validate() const;
};

class CoilThermalModel
{
   public:
	/** Builds the network (validates params). */
	explicit CoilThermalModel(const CoilThermalParams& params);

	const CoilThermalParams& params() const { return p_; }

	int coilNodeCount() const { return p_.layers * p_.sectors; }
	int nodeCount() const { return coilNodeCount() + 4; }
	int coilNode(int layer, int sector) const { return layer * p_.sectors + sector; }
	int hubNode() const { return coilNodeCount(); }
	int housingNode() const { return coilNodeCount() + 1; }
	int mountNode() const { return coilNodeCount() + 2; }
	int electronicsNode() const { return coilNodeCount() + 3; }
	/** Sector centre angle [deg]. */
	double sectorAngle_deg(int sector) const { return 360.0 * sector / p_.sectors; }

	/** Conductance matrix K [W/K] (symmetric, includes the conductances to air on the diagonal). */
	const Eigen::MatrixXd& conductance() const { return K_; }
	/** Heat capacities [J/K]. */
	const Eigen::VectorXd& capacity() const { return C_; }
	/** Conductance of each node to chamber air [W/K]. */
	const Eigen::VectorXd& airConductance() const { return g_air_; }
	/** Time constants of the network [s], ascending. */
	std::vector<double> timeConstants_s() const;

	/** Steady state for constant inputs: solves K T = g_air T_air + e_el P [degC]. */
	Eigen::VectorXd steadyState(double air_C, double power_W) const;

	/** Exact step of length dt_s with inputs varying linearly from (air0, P0) to (air1, P1).
	 * Precomputes (and caches) the transition for dt_s; throws if dt_s <= 0. */
	Eigen::VectorXd step(const Eigen::VectorXd& T, double dt_s, double air0_C, double air1_C, double p0_W, double p1_W);

	/** Mean temperature of one coil layer [degC]. */
	double layerMean_C(const Eigen::VectorXd& T, int layer) const;

   private:
	void prepare(double dt_s);

	CoilThermalParams p_;
	Eigen::MatrixXd K_;
	Eigen::VectorXd C_, g_air_, e_el_;
	// Modal form: T = S q, q' = -lambda q + S^-1 C^-1 (inputs)
	Eigen::VectorXd lambda_;
	Eigen::MatrixXd S_, Sinv_;
	double cached_dt_s_ = -1;
	Eigen::MatrixXd Phi_;  // state transition
	Eigen::MatrixXd G0_, G1_;  // input gains (n x 2): for inputs at step start and their change
};

}  // namespace mrpt_fog::sim
