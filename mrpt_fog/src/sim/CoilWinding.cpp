/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/CoilWinding.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::sim
{
constexpr EnumName<WindingPattern> kWindingPatterns[] = {{WindingPattern::Helical, "helical"},
														   {WindingPattern::Dipolar, "dipolar"},
														   {WindingPattern::Quadrupolar, "quadrupolar"},
														   {WindingPattern::Octupolar, "octupolar"}};

const char* toString(WindingPattern p) { return nameIn(kWindingPatterns, p, "octupolar"); }

WindingPattern windingPatternFromString(const std::string& s)
{
	if (const auto p = valueIn(kWindingPatterns, s)) return *p;
	throw std::invalid_argument("winding must be helical, dipolar, quadrupolar or octupolar, got '" + s + "'");
}

void WindingParams::validate() const
{
	if (!(fiber_length_m > 0)) throw std::invalid_argument("coil.fiber_length_m: must be > 0");
	if (!(mean_diameter_m > 0)) throw std::invalid_argument("coil.mean_diameter_m: must be > 0");
	if (fiber_layers < 1) throw std::invalid_argument("coil.fiber_layers: must be >= 1");
	if (!(std::abs(midpoint_offset_m) < 0.5 * fiber_length_m))
		throw std::invalid_argument("coil.midpoint_offset_m: must be within +-L/2");
	if (!(std::abs(layer_length_mismatch) < 0.5)) throw std::invalid_argument("coil.layer_length_mismatch: must be within +-0.5");
	if (!(refractive_index > 0)) throw std::invalid_argument("coil.refractive_index: must be > 0");
	if (!std::isfinite(dn_dT_per_K) || !std::isfinite(expansion_per_K))
		throw std::invalid_argument("coil.dn_dT_per_K / expansion_per_K: must be finite");
}

namespace
{
// Half of a symmetric winding that fills physical layer l.
bool layerFromHalfA(WindingPattern p, int l)
{
	switch (p)
	{
		case WindingPattern::Dipolar: return l % 2 == 0;
		case WindingPattern::Quadrupolar:
		{
			const int r = l % 4;
			return r == 0 || r == 3;
		}
		case WindingPattern::Octupolar:
		{
			static const bool pat[8] = {true, false, false, true, false, true, true, false};
			return pat[l % 8];
		}
		default: return false;
	}
}
}  // namespace

CoilWinding::CoilWinding(const WindingParams& params, int node_layers, int sectors)
	: p_(params), node_layers_(node_layers), sectors_(sectors)
{
	p_.validate();
	if (node_layers < 1 || sectors < 1) throw std::invalid_argument("CoilWinding: need at least one node");
	const int n = node_layers * sectors;
	w_ = Eigen::VectorXd::Zero(n);
	len_ = Eigen::VectorXd::Zero(n);
	const double L = p_.fiber_length_m;
	const double layer_len = L / p_.fiber_layers;
	const double turn_len = units::kPi * p_.mean_diameter_m;
	const double sector_len = turn_len / sectors;

	// Fibre still to wind in each half and where each half has got to (s from its start).
	const bool helical = p_.pattern == WindingPattern::Helical;
	const double z_m = helical ? 0.0 : 0.5 * L + p_.midpoint_offset_m;
	double left[2] = {z_m, L - z_m};  // A: towards z = 0, B: towards z = L
	double s_done[2] = {0.0, 0.0};

	for (int l = 0; l < p_.fiber_layers; l++)
	{
		const int node_layer = static_cast<int>(static_cast<long long>(l) * node_layers / p_.fiber_layers);
		int h = layerFromHalfA(p_.pattern, l) ? 0 : 1;
		double pos = 0;  // position along this layer [m]
		double fill = helical ? layer_len : layer_len * (h == 0 ? 1.0 + p_.layer_length_mismatch : 1.0 - p_.layer_length_mismatch);
		if (l == p_.fiber_layers - 1) fill = left[0] + left[1];  // absorb rounding
		while (fill > 1e-12)
		{
			if (left[h] <= 1e-12) h = 1 - h;
			if (left[h] <= 1e-12) break;
			const double take = std::min(fill, left[h]);
			// Split this stretch at sector boundaries (sector j spans centre +- half a sector).
			double done = 0;
			while (done < take - 1e-12)
			{
				const double p = pos + done;
				const double u = std::fmod(p + 0.5 * sector_len, turn_len);  // shifted so sector 0 starts at 0
				int sector = static_cast<int>(u / sector_len);
				if (sector >= sectors) sector = sectors - 1;
				const double to_boundary = (sector + 1) * sector_len - u;
				const double piece = std::min(take - done, std::max(to_boundary, 1e-9));
				const double s0 = s_done[h] + done, s1 = s0 + piece;
				double z0, z1;  // fibre coordinates, z0 < z1
				if (h == 0)
				{
					z0 = z_m - s1;
					z1 = z_m - s0;
				}
				else
				{
					z0 = z_m + s0;
					z1 = z_m + s1;
				}
				const int k = node_layer * sectors + sector;
				w_(k) += (z1 * z1 - z0 * z0) - L * (z1 - z0);
				len_(k) += piece;
				done += piece;
			}
			s_done[h] += take;
			left[h] -= take;
			pos += take;
			fill -= take;
		}
	}
}

double CoilWinding::shupeGain() const
{
	const double n = p_.refractive_index;
	return n * (p_.dn_dT_per_K + n * p_.expansion_per_K) / (p_.fiber_length_m * p_.mean_diameter_m);
}

double CoilWinding::shupeRate_rad_s(const Eigen::VectorXd& Tdot_K_s) const
{
	if (Tdot_K_s.size() < w_.size()) throw std::invalid_argument("CoilWinding::shupeRate_rad_s: too few node rates");
	return shupeGain() * w_.dot(Tdot_K_s.head(w_.size()));
}

}  // namespace mrpt_fog::sim
