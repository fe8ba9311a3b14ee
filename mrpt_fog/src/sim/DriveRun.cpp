/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/system/datetime.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/DriveRun.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <algorithm>
#include <cmath>

#include "SimulatedSeries.h"

namespace mrpt_fog::sim
{
DriveStep driveStep(std::size_t k, double rate_hz, const DriveTrajectory& traj, const ChamberProfile& cabin,
					FogSimulator& sim, const PlanarState& prev)
{
	const double dt = 1.0 / rate_hz;
	DriveStep step;
	step.t_s = static_cast<double>(k) / rate_hz;
	step.now = traj.at(step.t_s);
	ChamberState& st = step.chamber;
	st = cabin.stateAt(step.t_s);
	// Mean applied yaw rate over (t - dt, t], exact from the heading truth [deg/h].
	st.table_rate_dph = k == 0 ? step.now.yaw_rate_rad_s * units::kRadPerSecToDegPerHour
							   : (step.now.yaw_rad - prev.yaw_rad) / dt * units::kRadPerSecToDegPerHour;
	st.field_uT = 0;
	step.sample = k == 0 ? sim.start(st, cabin.initialState()) : sim.advance(dt, st);
	return step;
}

double simulateDriveSteps(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						  const OdometryErrors& odo, const DriveStepSink& f)
{
	settings.validate();
	const DriveTrajectory traj = DriveTrajectory::randomDrive(settings.seed, cabin.duration_s());
	FogSimulator sim(device, settings.effects, settings.seed);
	SimRandom rng_odo(settings.seed, RandomStream::Odometry);
	const double dt = 1.0 / settings.rate_hz;
	const std::size_t n = driveSampleCount(cabin, settings);
	double ox = 0, oy = 0, oyaw = 0;  // odometry pose (starts at the true initial pose: origin)
	double coil_min = 1e300, coil_max = -1e300;
	PlanarState prev = traj.at(0);
	bool more = true;
	DriveRecord r;
	r.epoch_s = device.epoch_s();
	for (std::size_t k = 0; k < n; k++)
	{
		const DriveStep step = driveStep(k, settings.rate_hz, traj, cabin, sim, prev);
		const PlanarState& now = step.now;
		const FogSample& s = step.sample;
		coil_min = std::min(coil_min, s.coil_mean_C);
		coil_max = std::max(coil_max, s.coil_mean_C);
		// Wheel odometry over the step.
		double v_odo = 0, w_odo = 0;
		if (k > 0)
		{
			const double ds = now.distance_m - prev.distance_m, dyaw = now.yaw_rad - prev.yaw_rad;
			double ds_o = ds * (1 + odo.scale_error), dyaw_o = dyaw * (1 + odo.yaw_scale_error);
			const double n1 = rng_odo.normal(), n2 = rng_odo.normal();  // drawn every step
			if (ds > 0)
			{
				ds_o += odo.distance_noise_m_rt_m * std::sqrt(ds) * n1;
				dyaw_o += odo.yaw_noise_rad_rt_m * std::sqrt(ds) * n2;
			}
			ox += ds_o * std::cos(oyaw + 0.5 * dyaw_o);
			oy += ds_o * std::sin(oyaw + 0.5 * dyaw_o);
			oyaw = std::remainder(oyaw + dyaw_o, 2 * units::kPi);
			v_odo = ds_o / dt;
			w_odo = dyaw_o / dt;
		}
		if (more && f)
		{
			r.t_s = step.t_s;
			r.sample = s;
			r.table_rate_dph = step.chamber.table_rate_dph;
			r.odo_x_m = ox, r.odo_y_m = oy, r.odo_yaw_rad = oyaw, r.odo_v_mps = v_odo, r.odo_w_rad_s = w_odo;
			r.truth_x_m = now.x_m, r.truth_y_m = now.y_m, r.truth_yaw_rad = std::remainder(now.yaw_rad, 2 * units::kPi);
			more = f(r);
		}
		prev = now;
	}
	return coil_max - coil_min;
}

std::size_t driveSampleCount(const ChamberProfile& cabin, const SimSettings& settings)
{
	return static_cast<std::size_t>(std::floor(cabin.duration_s() * settings.rate_hz + 1e-9)) + 1;
}

FogSeries driveRunHeader(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						 const OdometryErrors& odo, double coil_transient_C)
{
	FogSeries fog = emptySimulatedSeries(device);
	recordSimMetadata(fog, "vehicle", cabin, device, settings);
	const double duration_s = static_cast<double>(driveSampleCount(cabin, settings) - 1) / settings.rate_hz;
	const DriveTrajectory traj = DriveTrajectory::randomDrive(settings.seed, cabin.duration_s());
	fog.setMetadata("drive.odometry.scale_error", formatValue("%.10g", odo.scale_error));
	fog.setMetadata("drive.odometry.yaw_scale_error", formatValue("%.10g", odo.yaw_scale_error));
	fog.setMetadata("drive.odometry.distance_noise_m_rt_m", formatValue("%.10g", odo.distance_noise_m_rt_m));
	fog.setMetadata("drive.odometry.yaw_noise_rad_rt_m", formatValue("%.10g", odo.yaw_noise_rad_rt_m));
	fog.setMetadata("drive.coil_transient_C", formatValue("%.10g", coil_transient_C));
	fog.setMetadata("drive.distance_m", formatValue("%.10g", traj.at(duration_s).distance_m));
	fog.setMetadata("drive.streams", "FOG (thermal error), FOG_IDEAL (same noise, no thermal error), ODOMETRY, GROUND_TRUTH");
	return fog;
}

mrpt::obs::CObservation::Ptr odometryObservation(const DriveRecord& r)
{
	auto o = mrpt::obs::CObservationOdometry::Create();
	o->sensorLabel = "ODOMETRY";
	o->timestamp = mrpt::Clock::fromDouble(r.epoch_s + r.t_s);
	o->odometry = mrpt::poses::CPose2D(r.odo_x_m, r.odo_y_m, r.odo_yaw_rad);
	o->hasVelocities = true;
	o->velocityLocal = mrpt::math::TTwist2D(r.odo_v_mps, 0.0, r.odo_w_rad_s);
	return o;
}

mrpt::obs::CObservation::Ptr truthObservation(const DriveRecord& r)
{
	auto g = mrpt::obs::CObservationRobotPose::Create();
	g->sensorLabel = "GROUND_TRUTH";
	g->timestamp = mrpt::Clock::fromDouble(r.epoch_s + r.t_s);
	g->pose.mean = mrpt::poses::CPose3D(r.truth_x_m, r.truth_y_m, 0.0, r.truth_yaw_rad, 0.0, 0.0);
	g->pose.cov.setZero();
	return g;
}

DriveOutput simulateDrive(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						  const OdometryErrors& odo)
{
	settings.validate();
	const std::size_t n = driveSampleCount(cabin, settings);
	DriveOutput out;
	out.duration_s = static_cast<double>(n - 1) / settings.rate_hz;
	FogSeries& fog = out.fog;
	fog = emptySimulatedSeries(device);
	FogSeries& ideal = out.fog_ideal;
	ideal = fog;
	ideal.sensor_label = "FOG_IDEAL";

	std::vector<mrpt::obs::CObservation::Ptr> odo_obs, truth_obs;
	out.coil_transient_C = simulateDriveSteps(cabin, device, settings, odo, [&](const DriveRecord& r) {
		const FogSample& s = r.sample;
		for (FogSeries* f : {&fog, &ideal})
		{
			f->time_s.push_back(r.t_s);
			for (std::size_t i = 0; i < s.temp_C.size(); i++) f->temp_C[i].push_back(s.temp_C[i]);
			f->power.push_back(s.power_on ? 1.0 : 0.0);
			f->table_rate_dph.push_back(r.table_rate_dph);
		}
		// A gyro that is off gives no sample: an empty rate (NaN) where power is 0, not a 0 deg/h
		// a navigator would integrate as "no turn".
		fog.rate_dph[2].push_back(s.power_on ? s.rate_dph : NAN);
		ideal.rate_dph[2].push_back(s.power_on ? s.ideal_rate_dph : NAN);
		odo_obs.push_back(odometryObservation(r));
		truth_obs.push_back(truthObservation(r));
		return true;
	});

	const FogSeries h = driveRunHeader(cabin, device, settings, odo, out.coil_transient_C);
	fog.metadata = h.metadata;
	const auto fog_meta = fog.metadata;
	ideal.metadata = fog_meta;
	ideal.setMetadata("sim.effects", "none (ideal twin of FOG: same noise realisation)");

	// Interleave FOG_IDEAL, ODOMETRY, GROUND_TRUTH per sample (already in time order).
	const auto ideal_obs = observationsFromSeries(ideal);
	out.others.reserve(3 * n);
	for (std::size_t k = 0; k < n; k++)
	{
		out.others.push_back(ideal_obs[k]);
		out.others.push_back(odo_obs[k]);
		out.others.push_back(truth_obs[k]);
	}
	return out;
}

}  // namespace mrpt_fog::sim
