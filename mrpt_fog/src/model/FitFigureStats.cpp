/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/FitFigureStats.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog
{
void fitFiguresOfPasses(FitFigures& f, const RecordPass& comp, const RecordPass& raw, double tau_s)
{
	f.tau_s = tau_s;
	double sum = 0, sum2 = 0;
	std::size_t n = 0;
	comp([&](double, double v) {
		if (std::isfinite(v))
		{
			sum += v;
			n++;
		}
	});
	if (n == 0) return;
	const double mean = sum / static_cast<double>(n);
	comp([&](double, double v) {
		if (std::isfinite(v)) sum2 += (v - mean) * (v - mean);
	});
	f.samples = n;
	f.rms_dph = std::sqrt(sum2 / static_cast<double>(n));
	try
	{
		const BiasStats cs = biasStats(comp, tau_s), rs = biasStats(raw, tau_s);
		f.stability_dph = cs.stability_dph;
		f.range_dph = cs.range_dph;
		f.raw_stability_dph = rs.stability_dph;
		f.raw_range_dph = rs.range_dph;
		f.valid = true;
	}
	catch (const std::invalid_argument&)
	{
		f.valid = false;  // run shorter than 2 tau: RMS only
		f.stability_dph = f.range_dph = f.raw_stability_dph = f.raw_range_dph = std::numeric_limits<double>::quiet_NaN();
	}
}
}  // namespace mrpt_fog
