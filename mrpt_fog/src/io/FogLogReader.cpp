/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/UnitPlausibility.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "FogLogReaderImpl.h"

namespace mrpt_fog
{
namespace io::detail
{
std::string quoteForError(const char* data, std::size_t size)
{
	constexpr std::size_t kShown = 40;
	std::string out;
	const std::size_t n = std::min(size, kShown);
	for (std::size_t i = 0; i < n; i++)
	{
		const auto c = static_cast<unsigned char>(data[i]);
		if (c >= 0x20 && c < 0x7f) out += static_cast<char>(c);
		else
		{
			static const char* hex = "0123456789abcdef";
			out += "\\x";
			out += hex[c >> 4];
			out += hex[c & 15];
		}
	}
	if (size > kShown) out += "... (" + std::to_string(size) + " bytes)";
	return out;
}
}  // namespace io::detail

struct FogLogReader::Judge
{
	explicit Judge(DeclaredUnits d) : plausibility(std::move(d)) {}
	UnitPlausibility plausibility;
};

FogLogReader::FogLogReader(const std::string& path, const std::string& fog_label, const ReadLimits& limits,
						   ObservationSink others, const LogReadOptions& options)
	: path_(path), options_(options)
{
	const std::string ext = fileExtension(path);
	if (ext == ".rawlog") impl_ = makeRawlogReaderImpl(path, fog_label, limits, std::move(others));
	else if (ext == ".csv" || ext == ".csv.gz" || options.format)
	{
		impl_ = makeCsvReaderImpl(path, limits, options.format.get());
		if (!fog_label.empty() && impl_->header.sensor_label != fog_label)
			throw FogIoError(path + ": the CSV holds sensor '" + impl_->header.sensor_label + "', not '" + fog_label + "'");
	}
	else
		throw FogIoError(path + ": unknown file type '" + ext +
						 "' (expected .rawlog, .csv or .csv.gz, or a logger file read with a format file, --format)");
	const bool formatted = ext != ".rawlog" && options.format;
	judge_ = std::make_unique<Judge>(formatted ? DeclaredUnits::of(*options.format) : DeclaredUnits::native());
	if (options_.notice)
		for (const auto& n : impl_->notes()) options_.notice({LogNotice::Kind::Note, path_, n});
}

FogLogReader::~FogLogReader() = default;

bool FogLogReader::next(FogSample& s)
{
	if (impl_->next(s))
	{
		judge_->plausibility.add(s, s.power != 0.0);
		return true;
	}
	if (!ended_ && options_.notice)
		for (const auto& f : judge_->plausibility.findings())
			options_.notice({LogNotice::Kind::UnitWarning, path_, f.message()});
	ended_ = true;
	return false;
}

std::vector<std::string> FogLogReader::notes() const { return impl_->notes(); }
std::vector<UnitFinding> FogLogReader::unitFindings() const { return judge_->plausibility.findings(); }

const FogSeries& FogLogReader::header() const { return impl_->header; }
bool FogLogReader::hasTableRate() const { return !impl_->header.table_rate_dph.empty(); }
bool FogLogReader::hasField() const { return !impl_->header.field_uT.empty(); }
bool FogLogReader::hasPower() const { return !impl_->header.power.empty(); }
std::size_t FogLogReader::samplesRead() const { return impl_->samples; }
std::size_t FogLogReader::objectsRead() const { return impl_->objectsRead(); }
bool FogLogReader::isRawlog() const { return impl_->isRawlog(); }
std::uint64_t FogLogReader::fileBytesRead() const { return impl_->fileBytesRead(); }
std::uint64_t FogLogReader::fileBytes() const { return impl_->fileBytes(); }

namespace
{
/** One column in fixed-size blocks: appending never copies what was read, and the exact-size
 * column is made at the end (peak memory: the data once plus one column, instead of up to twice
 * every column while std::vector grows). */
class BlockColumn
{
   public:
	void push(double v)
	{
		if (used_ == kBlock || blocks_.empty())
		{
			blocks_.emplace_back(new double[kBlock]);
			used_ = 0;
		}
		blocks_.back()[used_++] = v;
		n_++;
	}
	/** Moves the values into `out` (exact size) and frees the blocks. */
	void moveTo(std::vector<double>& out)
	{
		out.clear();
		out.shrink_to_fit();
		out.resize(n_);
		std::size_t k = 0;
		for (auto& b : blocks_)
		{
			const std::size_t m = std::min(kBlock, n_ - k);
			std::copy(b.get(), b.get() + m, out.data() + k);
			k += m;
			b.reset();
		}
		blocks_.clear();
		n_ = used_ = 0;
	}

   private:
	static constexpr std::size_t kBlock = 1 << 16;
	std::vector<std::unique_ptr<double[]>> blocks_;
	std::size_t used_ = 0, n_ = 0;
};
}  // namespace

FogSeries readAllSamples(FogLogReader& r)
{
	FogSeries s = emptySeriesLike(r.header());
	const std::size_t nt = s.thermistors.size();
	BlockColumn time;
	std::array<BlockColumn, 3> rate;
	std::vector<BlockColumn> temp(nt);
	BlockColumn table, field, power;
	FogSample x;
	while (r.next(x))
	{
		time.push(x.time_s);
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) rate[a].push(x.rate_dph[a]);
		for (std::size_t i = 0; i < nt; i++) temp[i].push(x.temp_C[i]);
		if (r.hasTableRate()) table.push(x.table_rate_dph);
		if (r.hasField()) field.push(x.field_uT);
		if (r.hasPower()) power.push(x.power);
	}
	time.moveTo(s.time_s);
	for (int a = 0; a < 3; a++)
		if (s.has_axis[a]) rate[a].moveTo(s.rate_dph[a]);
	for (std::size_t i = 0; i < nt; i++) temp[i].moveTo(s.temp_C[i]);
	if (r.hasTableRate()) table.moveTo(s.table_rate_dph);
	if (r.hasField()) field.moveTo(s.field_uT);
	if (r.hasPower()) power.moveTo(s.power);
	return s;
}

void appendSample(FogSeries& s, const FogSample& x, const FogLogReader& r)
{
	s.time_s.push_back(x.time_s);
	for (int a = 0; a < 3; a++)
		if (s.has_axis[a]) s.rate_dph[a].push_back(x.rate_dph[a]);
	for (std::size_t i = 0; i < s.temp_C.size(); i++) s.temp_C[i].push_back(x.temp_C[i]);
	if (r.hasTableRate()) s.table_rate_dph.push_back(x.table_rate_dph);
	if (r.hasField()) s.field_uT.push_back(x.field_uT);
	if (r.hasPower()) s.power.push_back(x.power);
}

}  // namespace mrpt_fog
