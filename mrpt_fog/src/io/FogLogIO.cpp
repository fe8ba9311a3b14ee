/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/UnitPlausibility.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

namespace mrpt_fog
{
namespace
{
enum class LogKind
{
	Rawlog,
	Csv
};

LogKind kindOf(const std::string& path)
{
	const std::string ext = fileExtension(path);
	if (ext == ".rawlog") return LogKind::Rawlog;
	if (ext == ".csv" || ext == ".csv.gz") return LogKind::Csv;
	throw FogIoError(path + ": unknown file type '" + ext + "' (expected .rawlog, .csv or .csv.gz)");
}
}  // namespace

FogSeries readFogLog(const std::string& path, const std::string& fog_label, const LogReadOptions& options)
{
	if (fileExtension(path) == ".rawlog")
	{
		FogSeries s = readFogRawlog(path, fog_label).fog;
		if (options.notice)
			for (const auto& f : judgeUnits(s)) options.notice({LogNotice::Kind::UnitWarning, path, f.message()});
		return s;
	}
	if (!options.format) kindOf(path);  // the extension must be known
	FogLogReader reader(path, fog_label, ReadLimits{}, nullptr, options);
	return readAllSamples(reader);
}

void writeFogLog(const std::string& path, const FogSeries& series)
{
	if (kindOf(path) == LogKind::Rawlog) writeFogRawlog(path, series);
	else writeFogCsv(path, series);
}

std::vector<mrpt::obs::CObservation::Ptr> stockObservationsForRawlog(const FogSeries& fog)
{
	std::vector<mrpt::obs::CObservation::Ptr> out;
	out.reserve(2 * fog.size());
	const auto fogs = fogObservationsForRawlog(fog);  // exact timestamps
	for (std::size_t k = 1; k < fogs.size(); k++)
	{
		const auto& f = dynamic_cast<const CObservationFOG&>(*fogs[k]);
		out.push_back(f.toIMU());
		out.push_back(f.toRawDAQ());
	}
	return out;
}

}  // namespace mrpt_fog

namespace mrpt_fog
{
FogRun readFogRun(const std::string& path, const std::string& fog_label,
				  const std::function<void(double, double*, std::size_t)>& each,
				  const std::function<void(std::uint64_t, std::uint64_t, std::uint64_t)>& progress,
				  const LogReadOptions& options)
{
	FogLogReader reader(path, fog_label, ReadLimits{}, nullptr, options);
	const FogSeries& h = reader.header();
	FogRun run(h, reader.hasTableRate(), reader.hasField(), reader.hasPower());
	FogSeries chunk = emptySeriesLike(h);
	std::size_t k0 = 0;
	const auto store = [&]() {
		try
		{
			chunk.validate();
		}
		catch (const std::exception& e)
		{
			std::string msg = e.what();
			if (k0 > 0) msg += " (sample numbers counted from sample " + std::to_string(k0) + ")";
			throw FogIoError(path + ": sensor '" + chunk.sensor_label + "': " + msg);
		}
		for (std::size_t j = 0; j < chunk.size(); j++) run.append(chunk, j);
		k0 += chunk.size();
		chunk.resize(0);
	};
	FogSample x;
	while (reader.next(x))
	{
		if (each) each(x.time_s, x.temp_C.data(), x.temp_C.size());
		appendSample(chunk, x, reader);
		if (chunk.size() == FogRun::kChunkSamples) store();
		if (progress) progress(reader.samplesRead(), reader.fileBytesRead(), reader.fileBytes());
	}
	if (chunk.size() > 0 || k0 == 0) store();
	return run;
}
}  // namespace mrpt_fog
