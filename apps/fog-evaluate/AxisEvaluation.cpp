/* fog-evaluate: the figures of one gyro axis of a log, raw and (with a calibration) compensated. */
#include "AxisEvaluation.h"

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::evaluate
{
AxisReport evaluateAxis(const FogRun& run, const std::string& path, GyroAxis axis, const Calibration* cal,
						const std::string& cal_path, double tau_s)
{
	AxisReport r;
	r.axis = axis;
	const int a = static_cast<int>(axis);
	const auto biasAt = [](const FogSeries& c, std::size_t j, double rate) {
		if (!c.table_rate_dph.empty()) rate -= c.table_rate_dph[j];
		if (!c.power.empty() && c.power[j] == 0.0) rate = NAN;
		return rate;
	};
	const auto notePower = [&](const FogSeries& c, std::size_t j) { r.power_cycles.add(c.power.empty() ? NAN : c.power[j]); };
	if (cal)
	{
		// The compensated column first (the compensator's pass), then the raw column of the same
		// rows (a second pass over the run).
		RowSpill comp_rows(3);
		r.compensation = std::make_unique<CompensationResult>(compensateWithCalibration(
			*cal, cal_path, path, run,
			[&](const FogSeries& c, std::size_t, std::size_t j0, std::size_t m, const Compensator::Output* out) {
				for (std::size_t j = j0; j < j0 + m; j++)
				{
					const double row[3] = {c.time_s[j], 0.0, biasAt(c, j, out[j - j0].compensated_dph)};
					comp_rows.push(row);
				}
			}));
		RowSpill with_raw(3);
		RowSpill::Reader rd(comp_rows);
		run.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t j = 0; j < c.size(); j++)
			{
				const double* row_in = rd.next();
				notePower(c, j);
				const double row[3] = {row_in[0], biasAt(c, j, c.rate_dph[a][j]), row_in[2]};
				with_raw.push(row);
			}
		});
		r.rows = std::move(with_raw);
	}
	else
	{
		RowSpill rows(2);
		run.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t j = 0; j < c.size(); j++)
			{
				notePower(c, j);
				const double row[2] = {c.time_s[j], biasAt(c, j, c.rate_dph[a][j])};
				rows.push(row);
			}
		});
		r.rows = std::move(rows);
	}
	try
	{
		r.raw = evaluateRate(r.rows, 1, tau_s);
		if (cal) r.comp = std::make_unique<RateEvaluation>(evaluateRate(r.rows, 2, tau_s));
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(path + ": axis " + std::string(1, axisLetter(axis)) + ": " + e.what());
	}
	return r;
}
}  // namespace mrpt_fog::evaluate
