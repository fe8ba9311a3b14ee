/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/obs/Units.h>

#include <charconv>
#include <cmath>
#include <optional>

#include "RawlogCommon.h"

namespace mrpt_fog
{
using io::detail::fromTicks;
using io::detail::kTicksPerSecond;
using io::detail::ticksOf;

class FogLogWriter::Impl
{
   public:
	Impl(const std::string& path, const FogSeries& layout, RawlogForm form)
		: path_(path), layout_(layout), form_(form)
	{
		const std::string ext = fileExtension(path);
		if (ext == ".rawlog") rawlog_ = true;
		else if (ext != ".csv" && ext != ".csv.gz")
			throw FogIoError(path + ": unknown file type '" + ext + "' (expected .rawlog, .csv or .csv.gz)");
		if (form == RawlogForm::Stock && !rawlog_) throw FogIoError(path + ": the stock form is a rawlog (.rawlog)");
		try
		{
			io::requireOneLineMetadata(layout);
			if (form == RawlogForm::Stock && layout.thermistors.size() > 65535)
				throw std::invalid_argument(std::to_string(layout.thermistors.size()) +
											" thermistors exceed the 65535 channels of a CObservationRawDAQ");
		}
		catch (const std::exception& e)
		{
			throw FogIoError(path + ": cannot write: " + oneLineErrorMessage(e.what()));
		}
		has_table_ = !layout.table_rate_dph.empty();
		has_field_ = !layout.field_uT.empty();
		has_power_ = !layout.power.empty();
		epoch_ticks_ = ticksOf(mrpt::Clock::fromDouble(layout.epoch_s));
		try
		{
			out_.emplace(path);
		}
		catch (const std::exception& e)
		{
			throw FogIoError(e.what());
		}
		gz_ = std::make_unique<io::GzWriter>(out_->writePath(), rawlog_ || ext == ".csv.gz", rawlog_ ? 1 : 6, path);
		if (rawlog_)
		{
			arch_ = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CStream>>(*gz_);
		}
		else
			writeCsvHeader();
		proto_ = CObservationFOG::Create();
		proto_->sensorLabel = layout.sensor_label;
		for (std::size_t i = 0; i < layout.thermistors.size(); i++) proto_->addThermistor(layout.thermistors[i], NAN);
		for (int a = 0; a < 3; a++) proto_->hasAxis[a] = layout.has_axis[a];
		proto_->hasTableRate = has_table_;
		proto_->hasField = has_field_;
		proto_->hasPower = has_power_;
		if (form_ == RawlogForm::Stock)
		{
			const auto imu = proto_->toIMU();  // the stock objects' fixed fields, from the class's own conversion
			imu_clean_ = *imu;
			for (auto& present : imu_clean_.dataIsPresent) present = false;
			const auto daq = proto_->toRawDAQ();
			daq_ = *daq;
		}
	}

	void write(const FogSample& x)
	{
		check(x);
		if (rawlog_) writeRawlogSample(x);
		else writeCsvRow(x);
		samples_++;
	}

	void writeOther(const mrpt::obs::CObservation& o)
	{
		if (!rawlog_) throw FogIoError(path_ + ": a CSV has no place for other observations");
		writeMetadataComment(o.timestamp);
		serialize(o);
	}

	void close()
	{
		if (rawlog_ && form_ == RawlogForm::Fog && !comment_written_) writeMetadataComment(fromTicks(epoch_ticks_));
		gz_->close();
		try
		{
			out_->commit();
		}
		catch (const FogIoError&)
		{
			throw;
		}
		catch (const std::exception& e)
		{
			throw FogIoError(e.what());
		}
	}

	std::size_t samples_ = 0, objects_ = 0;

   private:
	[[noreturn]] void failSample(const std::string& what) const
	{
		throw FogIoError(path_ + ": cannot write sample " + std::to_string(samples_) + ": " + what);
	}

	void check(const FogSample& x)
	{
		if (!std::isfinite(x.time_s)) failSample("time_s is not finite");
		if (samples_ > 0 && !(x.time_s > last_t_))
			failSample("time " + io::formatNumber(x.time_s) + " s is not after the previous sample's (" +
					   io::formatNumber(last_t_) + " s); time_s must be strictly increasing");
		const bool off = has_power_ && x.power == 0.0;
		if (has_power_ && x.power != 0.0 && x.power != 1.0) failSample("power is neither 1 nor 0");
		for (int a = 0; a < 3; a++)
			if (layout_.has_axis[a] && !std::isfinite(x.rate_dph[a]) && !(off && std::isnan(x.rate_dph[a])))
				failSample(std::string("non-finite rate_") + axisLetter(static_cast<GyroAxis>(a)) + "_dph" +
						   (std::isnan(x.rate_dph[a]) ? " (a missing rate is allowed only where power is 0)" : ""));
		if (x.temp_C.size() != layout_.thermistors.size())
			failSample(std::to_string(x.temp_C.size()) + " temperatures for " + std::to_string(layout_.thermistors.size()) +
					   " thermistors");
		for (std::size_t i = 0; i < x.temp_C.size(); i++)
			if (std::isinf(x.temp_C[i])) failSample("infinite temp_" + layout_.thermistors[i].name + "_C");
		last_t_ = x.time_s;
	}

	// ---- rawlog
	void serialize(const mrpt::serialization::CSerializable& o)
	{
		try
		{
			*arch_ << o;
		}
		catch (const FogIoError&)
		{
			throw;
		}
		catch (const std::exception& e)
		{
			throw FogIoError(path_ + ": cannot write: " + oneLineErrorMessage(e.what()));
		}
		objects_++;
	}

	void writeMetadataComment(mrpt::Clock::time_point t)
	{
		if (comment_written_ || form_ != RawlogForm::Fog) return;
		comment_written_ = true;
		auto comment = mrpt::obs::CObservationComment::Create();
		comment->sensorLabel = layout_.sensor_label + "_METADATA";
		comment->text = io::formatFogRawlogMetadata(layout_);
		comment->timestamp = t;
		serialize(*comment);
	}

	void writeRawlogSample(const FogSample& x)
	{
		const int64_t ticks = epoch_ticks_ + std::llround(x.time_s * kTicksPerSecond);
		if (samples_ > 0 && ticks <= last_ticks_)
			failSample("time " + io::formatNumber(x.time_s) + " s is less than 100 ns after the previous sample's: a "
					   "rawlog's timestamps resolve 100 ns (MRPT's tick), so both would get the same timestamp");
		last_ticks_ = ticks;
		auto& o = *proto_;
		o.timestamp = fromTicks(ticks);
		for (int a = 0; a < 3; a++)
			if (layout_.has_axis[a]) o.rate_dph[a] = x.rate_dph[a];
		for (std::size_t i = 0; i < x.temp_C.size(); i++)
		{
			const bool ok = std::isfinite(x.temp_C[i]);  // NaN = dropout
			o.temp_C[i] = ok ? x.temp_C[i] : NAN;
			o.tempValid[i] = ok;
		}
		if (has_table_) o.tableRate_dph = x.table_rate_dph;
		if (has_field_) o.field_uT = x.field_uT;
		if (has_power_) o.powerOn = x.power != 0.0;
		writeMetadataComment(o.timestamp);
		if (form_ == RawlogForm::Fog) serialize(o);
		else
		{
			// What o.toIMU() / o.toRawDAQ() make, in reused objects (no allocation per sample).
			imu_ = imu_clean_;
			imu_.timestamp = o.timestamp;
			const mrpt::obs::TIMUDataIndex idx[3] = {mrpt::obs::IMU_WX, mrpt::obs::IMU_WY, mrpt::obs::IMU_WZ};
			for (int a = 0; a < 3; a++)
				if (o.hasAxis[a] && !std::isnan(o.rate_dph[a]))  // NaN: gyro off, no rate sample (left absent)
					imu_.set(idx[a], o.rate_dph[a] * units::kDegPerHourToRadPerSec);
			const double t = o.meanTemperature_C();
			if (std::isfinite(t)) imu_.set(mrpt::obs::IMU_TEMPERATURE, t);
			serialize(imu_);
			daq_.timestamp = o.timestamp;
			for (std::size_t i = 0; i < o.temp_C.size(); i++) daq_.AIN_double[i] = o.temperature_C(i);
			serialize(daq_);
		}
	}

	// ---- CSV
	void writeCsvHeader()
	{
		const FogSeries& s = layout_;
		std::string out;
		out += "# sensor: " + s.sensor_label + "\n";
		out += "# epoch_s: " + io::formatNumber(s.epoch_s) + "\n";
		for (const auto& t : s.thermistors)
			out += "# thermistor " + t.name + ": side=" + toString(t.side) + " angle_deg=" + io::formatNumber(t.angle_deg) + "\n";
		for (const auto& [k, v] : s.metadata)
		{
			if (k == "sensor" || k == "epoch_s" || k.rfind("thermistor ", 0) == 0) continue;  // written above
			out += k.empty() ? "# " + v + "\n" : "# " + k + ": " + v + "\n";
		}
		out += "time_s";
		const char* rates[3] = {"rate_x_dph", "rate_y_dph", "rate_z_dph"};
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) out += std::string(",") + rates[a];
		for (const auto& t : s.thermistors) out += ",temp_" + t.name + "_C";
		if (has_table_) out += ",table_rate_dph";
		if (has_field_) out += ",field_uT";
		if (has_power_) out += ",power";
		out += "\n";
		gz_->write(out);
	}

	void number(double v)
	{
		// The shortest text that reads back to v (io::formatNumber), without a string per cell.
		const double a = std::fabs(v);
		const bool fixed = v == 0.0 || (a >= 1e-4 && a < 1e16);
		const auto r = fixed ? std::to_chars(row_ + len_, row_ + sizeof(row_), v, std::chars_format::fixed)
							 : std::to_chars(row_ + len_, row_ + sizeof(row_), v);
		len_ = static_cast<std::size_t>(r.ptr - row_);
	}
	void cell(double v)
	{
		flushRowIfFull();
		row_[len_++] = ',';
		if (!std::isnan(v)) number(v);  // NaN = missing reading: empty cell
	}
	void flushRowIfFull()
	{
		if (len_ + 400 > sizeof(row_))
		{
			gz_->Write(row_, len_);
			len_ = 0;
		}
	}
	void writeCsvRow(const FogSample& x)
	{
		flushRowIfFull();
		number(x.time_s);
		for (int a = 0; a < 3; a++)
			if (layout_.has_axis[a]) cell(x.rate_dph[a]);
		for (double t : x.temp_C) cell(t);
		if (has_table_) cell(x.table_rate_dph);
		if (has_field_) cell(x.field_uT);
		if (has_power_) cell(x.power);
		row_[len_++] = '\n';
		gz_->Write(row_, len_);
		len_ = 0;
	}

	std::string path_;
	FogSeries layout_;
	RawlogForm form_;
	bool rawlog_ = false, has_table_ = false, has_field_ = false, has_power_ = false;
	bool comment_written_ = false;
	std::optional<AtomicOutput> out_;
	std::unique_ptr<io::GzWriter> gz_;
	std::unique_ptr<mrpt::serialization::CArchiveStreamBase<mrpt::io::CStream>> arch_;
	CObservationFOG::Ptr proto_;
	mrpt::obs::CObservationIMU imu_clean_, imu_;  // stock form
	mrpt::obs::CObservationRawDAQ daq_;
	int64_t epoch_ticks_ = 0, last_ticks_ = 0;
	double last_t_ = 0;
	char row_[8192];
	std::size_t len_ = 0;
};

FogLogWriter::FogLogWriter(const std::string& path, const FogSeries& layout, RawlogForm form)
	: impl_(std::make_unique<Impl>(path, layout, form))
{
}
FogLogWriter::~FogLogWriter() = default;
void FogLogWriter::write(const FogSample& s) { impl_->write(s); }
void FogLogWriter::writeOther(const mrpt::obs::CObservation& o) { impl_->writeOther(o); }
void FogLogWriter::close() { impl_->close(); }
std::size_t FogLogWriter::samplesWritten() const { return impl_->samples_; }
std::size_t FogLogWriter::objectsWritten() const { return impl_->objects_; }

}  // namespace mrpt_fog
