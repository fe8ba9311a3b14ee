/* fog-sim: physics simulation of a FOG with coil thermistors. */
#include "StreamedRun.h"

#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>

#include <mrpt/core/Clock.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

#include <cmath>
#include <deque>
#include <iostream>
#include <stdexcept>

namespace mrpt_fog::app
{
namespace
{
/** fog-sim's 100 s figures of the powered samples (when more than 2 over >= 200 s). */
void summariseOn(SimRunSummary& out, const RowSpill& on, double on_first, double on_last)
{
	if (!(on.rows() > 2 && on_last - on_first >= 200.0)) return;
	out.has_stats = true;
	out.stats = biasStats(
		[&](const RecordVisitor& v) {
			on.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
				for (std::size_t j = 0; j < n; j++) v(r[2 * j], r[2 * j + 1]);
			});
		},
		100.0);
}
}  // namespace

SimRunSummary writeChamberStreamed(const std::string& path, const sim::ChamberProfile& profile,
								   const sim::FogDevice& device, const sim::SimSettings& settings, double max_time_s,
								   const std::vector<std::pair<std::string, std::string>>& extra_metadata)
{
	FogSeries header = sim::chamberRunHeader(profile, device, settings);
	for (const auto& [k, v] : extra_metadata) header.setMetadata(k, v);
	SimRunSummary out;
	out.thermistors = header.thermistors;
	const std::size_t nt = header.thermistorCount();
	out.min_C.assign(nt, NAN);
	out.max_C.assign(nt, NAN);
	const bool table = !header.table_rate_dph.empty(), field = !header.field_uT.empty();
	FogLogWriter w(path, layoutHeaderOf(header, table, field, true));
	RowSpill on(2);  // powered samples: time, rate - table rate
	double on_first = NAN, on_last = NAN;
	FogSample x;
	sim::simulateChamberSamples(
		profile, device, settings, max_time_s,
		[&](double t, double rate, const std::vector<double>& temp_C, double table_dph, double field_uT, double power) {
			// FogSeries::validate()'s checks (writeFogRawlog / writeFogCsv ran it on the whole run)
			if (!std::isfinite(rate) && !(std::isnan(rate) && power == 0.0))
				throw std::runtime_error(path + ": cannot write: FOG series: non-finite rate_z_dph at sample " +
										 std::to_string(out.samples) +
											(std::isnan(rate) ? " (a missing rate is allowed only where power is 0)" : ""));
			for (std::size_t i = 0; i < nt; i++)
				if (std::isinf(temp_C[i]))
					throw std::runtime_error(path + ": cannot write: FOG series: infinite temp_" + header.thermistors[i].name +
											 "_C at sample " + std::to_string(out.samples));
			x.time_s = t;
			x.rate_dph = {NAN, NAN, rate};
			x.temp_C = temp_C;
			x.table_rate_dph = table ? table_dph : NAN;
			x.field_uT = field ? field_uT : NAN;
			x.power = power;
			w.write(x);
			// the summary (fog-sim's in-memory code: std::minmax_element, the powered samples)
			for (std::size_t i = 0; i < nt; i++)
			{
				if (out.samples == 0 || temp_C[i] < out.min_C[i]) out.min_C[i] = temp_C[i];
				if (out.samples == 0 || !(temp_C[i] < out.max_C[i])) out.max_C[i] = temp_C[i];
			}
			if (power != 0)
			{
				const double row[2] = {t, rate - (table ? table_dph : 0.0)};
				on.push(row);
				if (on.rows() == 1) on_first = t;
				on_last = t;
			}
			out.samples++;
			out.last_time_s = t;
		});
	if (out.samples < 2) throw std::invalid_argument("run has fewer than 2 samples (check --duration-s)");
	w.close();
	summariseOn(out, on, on_first, on_last);
	return out;
}

SimRunSummary writeDriveStreamed(const std::string& path, const sim::ChamberProfile& cabin, const sim::FogDevice& device,
								 const sim::SimSettings& settings, double max_time_s,
								 const std::vector<std::pair<std::string, std::string>>& extra_metadata)
{
	const sim::OdometryErrors odo;
	SimRunSummary out;
	// pass 1: the coil transient the metadata holds
	out.coil_transient_C = sim::simulateDriveSteps(cabin, device, settings, odo, {});
	FogSeries header = sim::driveRunHeader(cabin, device, settings, odo, out.coil_transient_C);
	for (const auto& [k, v] : extra_metadata) header.setMetadata(k, v);
	out.thermistors = header.thermistors;
	const std::size_t nt = header.thermistorCount();
	out.min_C.assign(nt, NAN);
	out.max_C.assign(nt, NAN);
	const bool rawlog = path.size() >= 7 && path.compare(path.size() - 7, 7, ".rawlog") == 0;
	if (!rawlog) std::cerr << "fog-sim: note: CSV holds the FOG stream only; odometry and truth need .rawlog\n";
	FogLogWriter w(path, layoutHeaderOf(header, true, false, true));
	// The ideal twin's observation of a step: observationFromSeries() on a one-sample series.
	FogSeries ideal = emptySeriesLike(header);
	ideal.sensor_label = "FOG_IDEAL";
	ideal.time_s.assign(1, 0.0);
	ideal.rate_dph[2].assign(1, 0.0);
	for (auto& c : ideal.temp_C) c.assign(1, 0.0);
	ideal.table_rate_dph.assign(1, 0.0);
	ideal.power.assign(1, 0.0);
	// writeFogRawlog's merge: the others before a FOG sample when their time is earlier, FOG first
	// on equal times (the FOG sample's time in ticks as the writer stamps it).
	const std::int64_t epoch_ticks = mrpt::Clock::fromDouble(header.epoch_s).time_since_epoch().count();
	const auto fogTime = [&](double t) {
		return mrpt::Clock::time_point(mrpt::Clock::duration(epoch_ticks + std::llround(t * 1e7)));
	};
	const bool cut = std::isfinite(max_time_s);
	const auto others_end = mrpt::Clock::fromDouble(header.epoch_s + (cut ? max_time_s : 0.0) + 1e-6);  // fog-sim's cut
	std::deque<mrpt::obs::CObservation::Ptr> pending;
	RowSpill on(2);  // powered samples: time, FOG - FOG_IDEAL
	double on_first = NAN, on_last = NAN;
	FogSample x;
	sim::simulateDriveSteps(cabin, device, settings, odo, [&](const sim::DriveRecord& r) {
		const double t = r.t_s;
		const sim::FogSample& s = r.sample;
		const double power = s.power_on ? 1.0 : 0.0;
		const bool fog_kept = t <= max_time_s + 1e-9;
		if (rawlog)
		{
			ideal.time_s[0] = t;
			ideal.rate_dph[2][0] = s.power_on ? s.ideal_rate_dph : NAN;  // off: no gyro sample
			for (std::size_t i = 0; i < nt; i++) ideal.temp_C[i][0] = s.temp_C[i];
			ideal.table_rate_dph[0] = r.table_rate_dph;
			ideal.power[0] = power;
			for (auto o : {mrpt::obs::CObservation::Ptr(observationFromSeries(ideal, 0)), sim::odometryObservation(r),
						   sim::truthObservation(r)})
				if (!cut || o->timestamp <= others_end) pending.push_back(o);
		}
		if (fog_kept)
		{
			if (!std::isfinite(s.rate_dph) && !(std::isnan(s.rate_dph) && power == 0.0))
				throw std::runtime_error(path + ": cannot write: FOG series: non-finite rate_z_dph at sample " +
										 std::to_string(out.samples));
			const auto ft = fogTime(t);
			while (!pending.empty() && pending.front()->timestamp < ft)
			{
				w.writeOther(*pending.front());
				pending.pop_front();
			}
			x.time_s = t;
			x.rate_dph = {NAN, NAN, power != 0.0 ? s.rate_dph : NAN};  // off: no gyro sample (empty cell)
			x.temp_C = s.temp_C;
			x.table_rate_dph = r.table_rate_dph;
			x.field_uT = NAN;
			x.power = power;
			w.write(x);
			for (std::size_t i = 0; i < nt; i++)
			{
				if (out.samples == 0 || s.temp_C[i] < out.min_C[i]) out.min_C[i] = s.temp_C[i];
				if (out.samples == 0 || !(s.temp_C[i] < out.max_C[i])) out.max_C[i] = s.temp_C[i];
			}
			if (power != 0)
			{
				const double row[2] = {t, s.rate_dph - s.ideal_rate_dph};
				on.push(row);
				if (on.rows() == 1) on_first = t;
				on_last = t;
			}
			out.samples++;
			out.last_time_s = t;
		}
		return t <= max_time_s + 1e-3;  // past both cuts: no more
	});
	if (out.samples < 2) throw std::invalid_argument("run has fewer than 2 samples (check --duration-s)");
	for (const auto& o : pending) w.writeOther(*o);
	w.close();
	summariseOn(out, on, on_first, on_last);
	return out;
}

}  // namespace mrpt_fog::app
