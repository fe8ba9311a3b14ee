/* fog-sim: physics simulation of a FOG with coil thermistors. */
#include "StreamedChamber.h"

#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::app
{
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
	if (on.rows() > 2 && on_last - on_first >= 200.0)
	{
		out.has_stats = true;
		out.stats = biasStats(
			[&](const RecordVisitor& v) {
				on.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
					for (std::size_t j = 0; j < n; j++) v(r[2 * j], r[2 * j + 1]);
				});
			},
			100.0);
	}
	return out;
}

}  // namespace mrpt_fog::app
