/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** drive-truth: the simulator's internal truth of a vehicle drive, sample by sample, next to what
 * a calibration's compensator makes of it (a diagnostic harness for the heading error budget;
 * it lives in tests/ because it reads the simulator's state, which no real log has).
 *
 *   drive-truth --seed N [--cabin NAME|FILE.yaml] [--effect ID]... [--cal CAL.yaml] -o OUT.csv
 *
 * The drive is fog-sim --profile drive's (same trajectory, cabin, device, seed: the FOG column
 * equals fog-sim's bit for bit, checked by the program against simulateDrive). Columns:
 *   t_s, power, applied_dph (yaw rate + Earth rate, mean over the sample), raw_dph, ideal_dph,
 *   coil_mean_C, inner_C, outer_C, electronics_C, t_on_s (time since power-on, -1 if unknown),
 *   thermistors (device order), sf_true_ppm (the scale-factor error the simulator applied),
 *   bias_true_dph (thermal error minus the scale-factor part, plus the constant bias: what a
 *   perfect bias model would subtract), comp_bias_dph, comp_dph (the calibration's compensator;
 *   NaN without --cal). */
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/DriveRun.h>
#include <mrpt_fog/sim/DriveTrajectory.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

int main(int argc, char** argv)
{
	try
	{
		std::uint64_t seed = 20240501;
		std::string cabin_arg = "drive_cabin", cal_path, out_path;
		std::vector<std::string> effect_args;
		for (int i = 1; i < argc; i++)
		{
			const std::string a = argv[i];
			auto next = [&]() -> std::string {
				if (i + 1 >= argc) throw std::invalid_argument(a + ": needs a value");
				return argv[++i];
			};
			if (a == "--seed") seed = std::stoull(next());
			else if (a == "--cabin") cabin_arg = next();
			else if (a == "--cal") cal_path = next();
			else if (a == "--effect") effect_args.push_back(next());
			else if (a == "-o") out_path = next();
			else throw std::invalid_argument("unknown argument " + a);
		}
		if (out_path.empty()) throw std::invalid_argument("-o OUT.csv is required");
		const ChamberProfile cabin = cabin_arg.size() > 5 && cabin_arg.substr(cabin_arg.size() - 5) == ".yaml"
										 ? ChamberProfile::fromFile(cabin_arg)
										 : ChamberProfile::preset(cabin_arg);
		SimSettings settings;
		settings.seed = seed;
		if (!effect_args.empty()) settings.effects = effectsFromSelection(effect_args);
		const FogDevice dev = FogDevice::defaultDevice();
		const double dt = 1.0 / settings.rate_hz;

		// The loop of simulateDrive (its steps: driveStep), keeping the simulator's state.
		const DriveTrajectory traj = DriveTrajectory::randomDrive(settings.seed, cabin.duration_s());
		FogSimulator sim(dev, settings.effects, settings.seed);
		const auto n = static_cast<std::size_t>(std::floor(cabin.duration_s() * settings.rate_hz + 1e-9)) + 1;
		const double earth_dph = sim.enabled(Effect::EarthRate)
									 ? units::kEarthRate_dph * std::sin(dev.latitude_deg * units::kDegToRad)
									 : 0.0;
		const bool sf_on = sim.enabled(Effect::ScaleFactorTemp);
		struct Row
		{
			double t, power, applied, raw, ideal, coil, inner, outer, elec, t_on, sf_ppm, bias_true;
			std::vector<double> temps;
		};
		std::vector<Row> rows;
		rows.reserve(n);
		PlanarState prev = traj.at(0);
		double t_on = std::numeric_limits<double>::quiet_NaN();
		bool was_on = false;
		for (std::size_t k = 0; k < n; k++)
		{
			const DriveStep step = driveStep(k, settings.rate_hz, traj, cabin, sim, prev);
			const PlanarState& now = step.now;
			const ChamberState& st = step.chamber;
			const FogSample& s = step.sample;
			if (k == 0) t_on = (cabin.initialState() == InitialThermalState::Cold && st.power_on) ? 0.0 : -1.0;
			else if (st.power_on && !was_on) t_on = 0.0;
			else if (st.power_on && t_on >= 0) t_on += dt;
			was_on = st.power_on;
			Row r;
			r.t = step.t_s;
			r.power = s.power_on ? 1 : 0;
			r.applied = st.table_rate_dph + earth_dph;
			r.raw = s.rate_dph;
			r.ideal = s.ideal_rate_dph;
			r.coil = s.coil_mean_C;
			r.inner = s.inner_C;
			r.outer = s.outer_C;
			r.elec = sim.nodeTemperatures_C()(sim.thermal().electronicsNode());
			r.t_on = t_on;
			r.sf_ppm = sf_on ? dev.errors.sf_ppm_per_C() * (s.coil_mean_C - dev.errors.sf_ref_C) : 0.0;
			r.bias_true = s.thermal_error_dph - 1e-6 * r.sf_ppm * r.applied + dev.errors.constant_bias_dph;
			r.temps = s.temp_C;
			rows.push_back(r);
			prev = now;
		}
		// Check against the simulator's own drive (the harness must not be a second simulator).
		const DriveOutput ref = simulateDrive(cabin, dev, settings);
		for (std::size_t k = 0; k < n; k++)
			if (ref.fog.rate_dph[2][k] != rows[k].raw || ref.fog.temp_C[0][k] != rows[k].temps[0])
				throw std::runtime_error("harness drive differs from simulateDrive at sample " + std::to_string(k));

		std::vector<double> cb(n, std::nan("")), cc(n, std::nan(""));
		if (!cal_path.empty())
		{
			const Calibration cal = loadCalibrationYaml(cal_path, GyroAxis::Z);
			const CompensatedSeries c = compensate(cal, ref.fog);
			cb = c.bias_dph;
			cc = c.compensated_dph;
		}
		std::ofstream f(out_path);
		f << "t_s,power,applied_dph,raw_dph,ideal_dph,coil_mean_C,inner_C,outer_C,electronics_C,t_on_s";
		for (const auto& th : dev.thermistors) f << "," << th.info.name;
		f << ",sf_true_ppm,bias_true_dph,comp_bias_dph,comp_dph\n";
		char buf[64];
		auto put = [&](double v) {
			std::snprintf(buf, sizeof buf, ",%.10g", v);
			f << buf;
		};
		for (std::size_t k = 0; k < n; k++)
		{
			const Row& r = rows[k];
			std::snprintf(buf, sizeof buf, "%.3f", r.t);
			f << buf;
			for (double v : {r.power, r.applied, r.raw, r.ideal, r.coil, r.inner, r.outer, r.elec, r.t_on}) put(v);
			for (double v : r.temps) put(v);
			for (double v : {r.sf_ppm, r.bias_true, cb[k], cc[k]}) put(v);
			f << "\n";
		}
		if (!f) throw std::runtime_error(out_path + ": write failed");
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "drive-truth: error: " << e.what() << "\n";
		return 1;
	}
}
