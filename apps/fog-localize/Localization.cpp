/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "Localization.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::localize
{
GyroOffRecovery gyroOffRecoveryFromString(const std::string& text)
{
	if (text == "refix") return GyroOffRecovery::Refix;
	if (text == "none") return GyroOffRecovery::None;
	throw std::invalid_argument("gyro-off recovery '" + text + "' is not refix|none");
}

void applyLikelihoodOptions(mrpt::maps::COccupancyGridMap2D& grid, const MclOptions& o, double laser_range_m)
{
	auto& lo = grid.likelihoodOptions;
	lo.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
	lo.LF_stdHit = static_cast<float>(o.lf_std_hit_m);
	lo.LF_zHit = 0.95f;
	lo.LF_zRandom = 0.05f;
	lo.LF_maxRange = static_cast<float>(laser_range_m);
	lo.LF_decimation = o.lf_decimation;
	lo.LF_maxCorrsDistance = static_cast<float>(3.0 * o.lf_std_hit_m);
	lo.enableLikelihoodCache = true;
}

namespace
{
/** Gordon-Salmond-Smith roughening: jitter std K * E * N^(-1/3) per dimension (x, y, heading). */
void roughen(mrpt::slam::CMonteCarloLocalization2D& pdf, double k)
{
	auto& parts = pdf.m_particles;
	const std::size_t n = parts.size();
	if (n < 2 || !(k > 0)) return;
	const double phi0 = parts[0].d.phi;
	double lo[3] = {parts[0].d.x, parts[0].d.y, 0.0}, hi[3] = {lo[0], lo[1], 0.0};
	for (const auto& p : parts)
	{
		const double v[3] = {p.d.x, p.d.y, mrpt::math::wrapToPi(p.d.phi - phi0)};
		for (int j = 0; j < 3; ++j)
		{
			lo[j] = std::min(lo[j], v[j]);
			hi[j] = std::max(hi[j], v[j]);
		}
	}
	const double c = k * std::pow(static_cast<double>(n), -1.0 / 3.0);
	auto& rng = mrpt::random::getRandomGenerator();
	for (auto& p : parts)
	{
		p.d.x += c * (hi[0] - lo[0]) * rng.drawGaussian1D_normalized();
		p.d.y += c * (hi[1] - lo[1]) * rng.drawGaussian1D_normalized();
		p.d.phi = mrpt::math::wrapToPi(p.d.phi + c * (hi[2] - lo[2]) * rng.drawGaussian1D_normalized());
	}
}
}  // namespace

MclRun runMcl(const World& world, const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
			  const std::vector<double>& t, const std::vector<mrpt::poses::CPose2D>& odo,
			  const std::vector<StepSource>& step_source, const std::vector<Refix>& refixes,
			  const mrpt::poses::CPose2D& start, const MclOptions& o, std::uint32_t seed)
{
	if (scans.size() != t.size() || odo.size() != t.size() || t.size() < 2 ||
		(!step_source.empty() && step_source.size() != t.size()))
		throw std::invalid_argument("runMcl: scans, times and odometry differ in size or have fewer than 2 steps");
	mrpt::random::getRandomGenerator().randomize(seed);

	mrpt::slam::CMonteCarloLocalization2D pdf(o.particles);
	pdf.options.metricMap = world.grid;
	const double dyaw = o.init_yaw_deg * M_PI / 180.0;
	const auto drawAround = [&](const mrpt::poses::CPose2D& p) {
		pdf.resetUniform(p.x() - o.init_xy_m, p.x() + o.init_xy_m, p.y() - o.init_xy_m, p.y() + o.init_xy_m,
						 p.phi() - dyaw, p.phi() + dyaw, static_cast<int>(o.particles));
	};
	drawAround(start);
	std::size_t next_fix = 0;

	mrpt::bayes::CParticleFilter pf;
	pf.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	pf.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
	pf.m_options.adaptiveSampleSize = false;
	pf.m_options.BETA = 0.5;
	pf.m_options.powFactor = o.pow_factor;

	MclRun run;
	auto record = [&](double tk, double scale, bool wheel_only = false) {
		run.wheel_only.push_back(wheel_only);
		const auto [cov, m] = pdf.getCovarianceAndMean();
		run.t_s.push_back(tk);
		run.x_m.push_back(m.x());
		run.y_m.push_back(m.y());
		run.yaw_rad.push_back(m.phi());
		run.yaw_std_rad.push_back(std::sqrt(std::max(0.0, cov(2, 2))));
		run.odometry_scale.push_back(scale);
	};
	record(t[0], 1.0);

	double scale = 1.0, sum_est_m = 0.0, sum_odo_m = 0.0;
	std::size_t window_start = 0;  // first index of the current urban window
	const Stretch* current = &stretchAt(world.stretches, t[0]);
	for (std::size_t k = 1; k < t.size(); ++k)
	{
		while (next_fix < refixes.size() && refixes[next_fix].scan < k)
		{
			if (refixes[next_fix].scan == k - 1) drawAround(refixes[next_fix].pose);
			++next_fix;
		}
		mrpt::poses::CPose2D incr = odo[k] - odo[k - 1];
		incr.x(incr.x() * scale);
		incr.y(incr.y() * scale);
		mrpt::obs::CActionRobotMovement2D act;
		act.timestamp = mrpt::Clock::fromDouble(t[k]);
		const bool wheel_only = !step_source.empty() && step_source[k] == StepSource::WheelOnly;
		act.computeFromOdometry(incr, wheel_only ? o.wheel_only_motion : o.motion.toMrpt(t[k] - t[k - 1]));
		mrpt::obs::CActionCollection acts;
		acts.insert(act);
		mrpt::obs::CSensoryFrame sf;
		sf.insert(scans[k]);
		mrpt::bayes::CParticleFilter::TParticleFilterStats stats;
		pf.executeOn(pdf, &acts, &sf, &stats);
		if (stats.ESS_beforeResample < pf.m_options.BETA)
		{
			++run.resamplings;
			if (o.roughening_k > 0)
			{
				roughen(pdf, o.roughening_k);
				++run.roughenings;
			}
		}
		record(t[k], scale, wheel_only);

		// Online odometry-scale calibration at the end of each urban stretch.
		const Stretch* s = &stretchAt(world.stretches, t[k]);
		if (s != current)
		{
			if (o.calibrate_odometry_scale && current->kind == StretchKind::Urban)
			{
				std::size_t a = window_start;
				while (a < k && t[a] < current->t_begin_s + o.settle_s) ++a;
				// Sum of chords over sub-windows of ~chord_s: each chord is nearly the path length
				// for both the estimate and the odometry, so a heading error of the odometry (which
				// would change one long chord of a winding window) does not bias the ratio.
				double est = 0, od = 0;
				for (std::size_t b = a; b + 1 < k;)
				{
					std::size_t c = b;
					while (c + 1 < k && t[c] < t[b] + o.chord_s) ++c;
					est += std::hypot(run.x_m[c] - run.x_m[b], run.y_m[c] - run.y_m[b]);
					od += std::hypot(odo[c].x() - odo[b].x(), odo[c].y() - odo[b].y());
					b = c;
				}
				if (od > 300.0)
				{
					sum_est_m += est;
					sum_odo_m += od;
					scale = sum_est_m / sum_odo_m;
				}
			}
			current = s;
			window_start = k;
		}
	}
	return run;
}

}  // namespace mrpt_fog::localize
