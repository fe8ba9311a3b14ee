/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/CoilThermalModel.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::sim
{
void CoilThermalParams::validate() const
{
	if (layers < 2) throw std::invalid_argument("thermal.layers: must be >= 2");
	if (sectors < 4) throw std::invalid_argument("thermal.sectors: must be >= 4");
	const std::pair<const char*, double> positive[] = {
		{"mean_diameter_m", mean_diameter_m},
		{"radial_thickness_m", radial_thickness_m},
		{"axial_height_m", axial_height_m},
		{"volumetric_heat_capacity_J_m3K", volumetric_heat_capacity_J_m3K},
		{"radial_conductivity_W_mK", radial_conductivity_W_mK},
		{"tangential_conductivity_W_mK", tangential_conductivity_W_mK},
		{"hub_capacity_J_K", hub_capacity_J_K},
		{"hub_to_inner_W_K", hub_to_inner_W_K},
		{"housing_capacity_J_K", housing_capacity_J_K},
		{"housing_to_air_W_K", housing_to_air_W_K},
		{"mount_capacity_J_K", mount_capacity_J_K},
		{"electronics_capacity_J_K", electronics_capacity_J_K},
		{"electronics_to_housing_W_K", electronics_to_housing_W_K},
	};
	for (const auto& [name, v] : positive)
		if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("thermal.") + name + ": must be > 0");
	const std::pair<const char*, double> nonneg[] = {
		{"outer_to_housing_W_K", outer_to_housing_W_K}, {"faces_to_housing_W_K", faces_to_housing_W_K},
		{"mount_to_air_W_K", mount_to_air_W_K},			{"mount_to_housing_W_K", mount_to_housing_W_K},
		{"mount_to_hub_W_K", mount_to_hub_W_K},			{"mount_to_coil_W_K", mount_to_coil_W_K},
		{"electronics_to_coil_W_K", electronics_to_coil_W_K}, {"electronics_power_W", electronics_power_W},
	};
	for (const auto& [name, v] : nonneg)
		if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("thermal.") + name + ": must be >= 0");
	if (radial_thickness_m >= mean_diameter_m)
		throw std::invalid_argument("thermal.radial_thickness_m: must be smaller than mean_diameter_m");
}

namespace
{
// Weights (summing to 1) of sectors within +-half_width_deg of centre_deg, cos^2 shaped.
std::vector<double> angularWeights(int sectors, double centre_deg, double half_width_deg)
{
	std::vector<double> w(sectors, 0.0);
	double sum = 0;
	for (int j = 0; j < sectors; j++)
	{
		double d = std::remainder(360.0 * j / sectors - centre_deg, 360.0);
		if (std::abs(d) < half_width_deg)
		{
			const double c = std::cos(0.5 * units::kPi * d / half_width_deg);
			w[j] = c * c;
			sum += w[j];
		}
	}
	for (auto& x : w) x /= sum;
	return w;
}
}  // namespace

CoilThermalModel::CoilThermalModel(const CoilThermalParams& params) : p_(params)
{
	p_.validate();
	const int L = p_.layers, S = p_.sectors, n = nodeCount();
	K_ = Eigen::MatrixXd::Zero(n, n);
	C_ = Eigen::VectorXd::Zero(n);
	g_air_ = Eigen::VectorXd::Zero(n);
	e_el_ = Eigen::VectorXd::Zero(n);

	auto link = [&](int a, int b, double g) {
		K_(a, a) += g;
		K_(b, b) += g;
		K_(a, b) -= g;
		K_(b, a) -= g;
	};

	const double r_in = 0.5 * p_.mean_diameter_m - 0.5 * p_.radial_thickness_m;
	const double dr = p_.radial_thickness_m / L;
	const double h = p_.axial_height_m;
	const double dphi = 2 * units::kPi / S;
	for (int i = 0; i < L; i++)
	{
		const double r0 = r_in + i * dr, r1 = r0 + dr, rc = r0 + 0.5 * dr;
		const double volume = 0.5 * dphi * (r1 * r1 - r0 * r0) * h;
		for (int j = 0; j < S; j++)
		{
			const int a = coilNode(i, j);
			C_(a) = p_.volumetric_heat_capacity_J_m3K * volume;
			// around: to the next sector of the same layer
			link(a, coilNode(i, (j + 1) % S), p_.tangential_conductivity_W_mK * dr * h / (rc * dphi));
			// radially: to the next layer (cylindrical shell between the two centres)
			if (i + 1 < L)
			{
				const double rc1 = rc + dr;
				link(a, coilNode(i + 1, j), p_.radial_conductivity_W_mK * dphi * h / std::log(rc1 / rc));
			}
			link(a, housingNode(), p_.faces_to_housing_W_K / coilNodeCount());
		}
	}
	const auto wMount = angularWeights(S, 0.0, 60.0);
	const auto wElec = angularWeights(S, 180.0, 60.0);
	for (int j = 0; j < S; j++)
	{
		link(coilNode(0, j), hubNode(), p_.hub_to_inner_W_K / S);
		link(coilNode(L - 1, j), housingNode(), p_.outer_to_housing_W_K / S);
		for (int i = 0; i < L; i++)
			if (wMount[j] > 0) link(coilNode(i, j), mountNode(), p_.mount_to_coil_W_K * wMount[j] / L);
		if (wElec[j] > 0) link(coilNode(L - 1, j), electronicsNode(), p_.electronics_to_coil_W_K * wElec[j]);
	}
	C_(hubNode()) = p_.hub_capacity_J_K;
	C_(housingNode()) = p_.housing_capacity_J_K;
	C_(mountNode()) = p_.mount_capacity_J_K;
	C_(electronicsNode()) = p_.electronics_capacity_J_K;
	link(housingNode(), mountNode(), p_.mount_to_housing_W_K);
	link(hubNode(), mountNode(), p_.mount_to_hub_W_K);
	link(electronicsNode(), housingNode(), p_.electronics_to_housing_W_K);
	g_air_(housingNode()) = p_.housing_to_air_W_K;
	g_air_(mountNode()) = p_.mount_to_air_W_K;
	for (int a = 0; a < n; a++) K_(a, a) += g_air_(a);
	e_el_(electronicsNode()) = 1.0;

	// Modal decomposition of the symmetric M = C^-1/2 K C^-1/2 = V diag(lambda) V^T.
	const Eigen::VectorXd cs = C_.cwiseSqrt(), ci = cs.cwiseInverse();
	const Eigen::MatrixXd M = ci.asDiagonal() * K_ * ci.asDiagonal();
	Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M);
	if (es.info() != Eigen::Success) throw std::runtime_error("CoilThermalModel: eigen decomposition failed");
	lambda_ = es.eigenvalues();
	if (lambda_.minCoeff() <= 0)
		throw std::invalid_argument("CoilThermalModel: network has no path to chamber air (a mode does not decay)");
	S_ = ci.asDiagonal() * es.eigenvectors();
	Sinv_ = es.eigenvectors().transpose() * cs.asDiagonal();
}

std::vector<double> CoilThermalModel::timeConstants_s() const
{
	std::vector<double> tau(lambda_.size());
	for (int k = 0; k < lambda_.size(); k++) tau[k] = 1.0 / lambda_(k);
	std::sort(tau.begin(), tau.end());
	return tau;
}

Eigen::VectorXd CoilThermalModel::steadyState(double air_C, double power_W) const
{
	const Eigen::VectorXd rhs = g_air_ * air_C + e_el_ * power_W;
	return K_.ldlt().solve(rhs);
}

void CoilThermalModel::prepare(double dt_s)
{
	if (!(dt_s > 0) || !std::isfinite(dt_s)) throw std::invalid_argument("CoilThermalModel::step: dt must be > 0");
	const int n = nodeCount();
	Eigen::VectorXd e(n), a(n), b(n);
	for (int k = 0; k < n; k++)
	{
		const double lam = lambda_(k), x = lam * dt_s;
		const double one_minus_e = -std::expm1(-x);
		e(k) = 1.0 - one_minus_e;
		a(k) = one_minus_e / lam;  // int_0^dt exp(-lam (dt - s)) ds
		// (1/dt) int_0^dt exp(-lam (dt - s)) s ds, with its series for small x
		b(k) = x < 1e-4 ? dt_s * (0.5 - x / 6.0 + x * x / 24.0) : (1.0 - one_minus_e / x) / lam;
	}
	Eigen::MatrixXd B(n, 2);
	B.col(0) = g_air_.cwiseQuotient(C_);
	B.col(1) = e_el_.cwiseQuotient(C_);
	const Eigen::MatrixXd SinvB = Sinv_ * B;
	Phi_ = S_ * e.asDiagonal() * Sinv_;
	G0_ = S_ * a.asDiagonal() * SinvB;
	G1_ = S_ * b.asDiagonal() * SinvB;
	cached_dt_s_ = dt_s;
}

Eigen::VectorXd CoilThermalModel::step(const Eigen::VectorXd& T, double dt_s, double air0_C, double air1_C, double p0_W, double p1_W)
{
	if (dt_s != cached_dt_s_) prepare(dt_s);
	if (T.size() != nodeCount()) throw std::invalid_argument("CoilThermalModel::step: wrong state size");
	const Eigen::Vector2d u0(air0_C, p0_W), du(air1_C - air0_C, p1_W - p0_W);
	return Phi_ * T + G0_ * u0 + G1_ * du;
}

double CoilThermalModel::layerMean_C(const Eigen::VectorXd& T, int layer) const
{
	double s = 0;
	for (int j = 0; j < p_.sectors; j++) s += T(coilNode(layer, j));
	return s / p_.sectors;
}

}  // namespace mrpt_fog::sim
