/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt_fog/io/RawlogObjectReader.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/HeadingWithoutTruth.h>
#include <mrpt_fog_nav/Rotation.h>

#include <cmath>
#include <memory>

namespace mrpt_fog::heading
{
namespace
{
/** Sums for a least-squares slope of y on t (t relative to t_ref). */
struct SlopeSums
{
	double t_ref = 0, n = 0, st = 0, sy = 0, stt = 0, sty = 0, syy = 0;
	void add(double t, double y)
	{
		if (n == 0) t_ref = t;
		t -= t_ref;
		n++, st += t, sy += y, stt += t * t, sty += t * y, syy += y * y;
	}
	double sxx() const { return stt - st * st / n; }
	double sxy() const { return sty - st * sy / n; }
	double slope() const { return n >= 2 && sxx() > 0 ? sxy() / sxx() : std::numeric_limits<double>::quiet_NaN(); }
	double rmsAboutMean() const { return n > 0 ? std::sqrt(std::max(0.0, syy / n - (sy / n) * (sy / n))) : NAN; }
};

enum class Block
{
	Turn,
	Straight,
	Other
};

class Analysis
{
   public:
	Analysis(const std::string& path, const Calibration& cal, const NoTruthOptions& o) : path_(path), o_(o)
	{
		FogSeries header;
		{
			FogLogReader first(path, o.fog_label);
			header = first.header();
		}
		PipelineOptions popt = o.pipeline;
		popt.alignment = Alignment::ByCaller;
		if (!std::isfinite(popt.latitude_deg))
		{
			const auto lat = latitudeOf(header);
			if (!lat) throw std::runtime_error(path + ": no latitude_deg in the FOG's metadata; give the drive's latitude");
			popt.latitude_deg = *lat;
		}
		r_.latitude_deg = popt.latitude_deg;
		raw_ = std::make_unique<HeadingPipeline>(header, popt, nullptr);
		comp_ = std::make_unique<HeadingPipeline>(header, popt, &cal);
		r_.earth = comp_->earthRate();
		samples_ = std::make_unique<FogObservationSamples>(header, path);
	}

	NoTruthReport run()
	{
		RawlogObjectReader reader(path_);
		while (auto obj = reader.next())
		{
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) observation(*o, reader.objectsRead() - 1);
			else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
				for (const auto& so : *sf) observation(*so, reader.objectsRead() - 1);
		}
		closeBlock(true);
		r_.fog_samples = samples_->samples();
		r_.start_s = first_t_;
		r_.duration_s = last_t_ - first_t_;
		r_.final_difference_deg = diff_deg_;
		if (pooled_sxx_ > 0) r_.pooled_slope_dph = pooled_sxy_ / pooled_sxx_ * 3600.0;
		if (gps_raw_.n >= 2)
		{
			CourseFigures g;
			g.fixes = static_cast<std::size_t>(gps_raw_.n);
			g.raw_rms_deg = gps_raw_.rmsAboutMean();
			g.compensated_rms_deg = gps_comp_.rmsAboutMean();
			g.raw_slope_dph = gps_raw_.slope() * 3600.0;
			g.compensated_slope_dph = gps_comp_.slope() * 3600.0;
			g.from_rmc = from_rmc_;
			r_.gps = g;
		}
		return r_;
	}

   private:
	void observation(const mrpt::obs::CObservation& o, std::size_t index)
	{
		if (const auto* f = dynamic_cast<const CObservationFOG*>(&o); f && f->sensorLabel == o_.fog_label)
			fog(*f, index);
		else if (const auto* g = dynamic_cast<const mrpt::obs::CObservationGPS*>(&o))
			gps(*g);
	}

	void fog(const CObservationFOG& f, std::size_t index)
	{
		samples_->toSample(f, index, x_);
		const double t_abs = mrpt::Clock::toDouble(f.timestamp);
		if (!raw_->aligned())
		{
			raw_->align(t_abs, 0, 0, 0);
			comp_->align(t_abs, 0, 0, 0);
			first_t_ = t_abs;
			block_t0_ = t_abs;
		}
		const RateStep& rs = raw_->addFog(x_);
		const RateStep& cs = comp_->addFog(x_);
		const double raw_h = rs.heading_rad, comp_h = cs.heading_rad;
		diff_deg_ = nav::wrapToPi(comp_h - raw_h) * units::kRadToDeg;
		comp_heading_ = comp_h, raw_heading_ = raw_h;
		last_t_ = t_abs;
		// 1 s blocks of the compensated rate
		if (cs.integrated) block_angle_rad_ += nav::wrapToPi(comp_h - prev_comp_h_);
		prev_comp_h_ = comp_h;
		if (t_abs - block_t0_ >= 1.0) closeBlock(false);
	}

	void closeBlock(bool last)
	{
		const double dt = last_t_ - block_t0_;
		if (dt <= 0) return;
		const double rate_dps = block_angle_rad_ * units::kRadToDeg / dt;
		const Block b = std::abs(rate_dps) > o_.turn_rate_dps		 ? Block::Turn
						: std::abs(rate_dps) < o_.straight_rate_dps ? Block::Straight
																	 : Block::Other;
		if (b != seg_kind_ || last)
		{
			endSegment();
			seg_kind_ = b;
			seg_t0_ = block_t0_;
			seg_diff0_ = seg_diff_last_;
			seg_turned_deg_ = 0;
			seg_ = SlopeSums{};
		}
		seg_turned_deg_ += block_angle_rad_ * units::kRadToDeg;
		seg_.add(last_t_, diff_deg_);
		seg_t1_ = last_t_;
		seg_diff_last_ = diff_deg_;
		block_t0_ = last_t_;
		block_angle_rad_ = 0;
		if (last) endSegment();
	}

	void endSegment()
	{
		if (seg_.n == 0) return;
		if (seg_kind_ == Block::Turn)
			r_.turns.push_back({seg_t0_, seg_t1_, seg_turned_deg_, seg_diff_last_ - seg_diff0_});
		else if (seg_kind_ == Block::Straight && seg_t1_ - seg_t0_ >= o_.min_straight_s && seg_.n >= 2)
		{
			r_.straights.push_back({seg_t0_, seg_t1_, seg_.slope() * 3600.0});
			pooled_sxx_ += seg_.sxx();
			pooled_sxy_ += seg_.sxy();
		}
		seg_.n = 0;
	}

	void gps(const mrpt::obs::CObservationGPS& g)
	{
		if (!raw_->aligned()) return;
		double course_deg = NAN, speed = NAN;
		if (g.hasMsgClass<mrpt::obs::gnss::Message_NMEA_RMC>())
		{
			const auto& rmc = g.getMsgByClass<mrpt::obs::gnss::Message_NMEA_RMC>();
			if (rmc.fields.validity_char != 'A') return;
			speed = rmc.fields.speed_knots * 1852.0 / 3600.0;
			course_deg = rmc.fields.direction_degrees;
			from_rmc_ = true;
		}
		else if (g.hasMsgClass<mrpt::obs::gnss::Message_NMEA_GGA>())
		{
			const auto& gga = g.getMsgByClass<mrpt::obs::gnss::Message_NMEA_GGA>();
			if (gga.fields.fix_quality == 0) return;
			const double t = mrpt::Clock::toDouble(g.timestamp);
			const double lat = gga.fields.latitude_degrees * units::kDegToRad, lon = gga.fields.longitude_degrees * units::kDegToRad;
			if (std::isfinite(prev_gga_t_) && t > prev_gga_t_)
			{
				const double dn = (lat - prev_lat_) * 6378137.0, de = (lon - prev_lon_) * 6378137.0 * std::cos(lat);
				speed = std::hypot(dn, de) / (t - prev_gga_t_);
				course_deg = std::atan2(de, dn) * units::kRadToDeg;
			}
			prev_gga_t_ = t, prev_lat_ = lat, prev_lon_ = lon;
		}
		if (!(speed > o_.gps_min_speed_mps) || !std::isfinite(course_deg)) return;
		const double yaw_cog = nav::wrapToPi((90.0 - course_deg) * units::kDegToRad);  // ENU yaw of the course
		const double t = mrpt::Clock::toDouble(g.timestamp);
		const double er = nav::wrapToPi(raw_heading_ - yaw_cog), ec = nav::wrapToPi(comp_heading_ - yaw_cog);
		if (gps_raw_.n == 0) ref_raw_ = er, ref_comp_ = ec;
		gps_raw_.add(t, nav::wrapToPi(er - ref_raw_) * units::kRadToDeg);
		gps_comp_.add(t, nav::wrapToPi(ec - ref_comp_) * units::kRadToDeg);
	}

	std::string path_;
	NoTruthOptions o_;
	std::unique_ptr<HeadingPipeline> raw_, comp_;
	std::unique_ptr<FogObservationSamples> samples_;
	FogSample x_;
	NoTruthReport r_;
	double first_t_ = 0, last_t_ = 0, diff_deg_ = 0, comp_heading_ = 0, raw_heading_ = 0, prev_comp_h_ = 0;
	double block_t0_ = 0, block_angle_rad_ = 0;
	Block seg_kind_ = Block::Other;
	double seg_t0_ = 0, seg_t1_ = 0, seg_diff0_ = 0, seg_diff_last_ = 0, seg_turned_deg_ = 0;
	SlopeSums seg_;
	double pooled_sxx_ = 0, pooled_sxy_ = 0;
	SlopeSums gps_raw_, gps_comp_;
	double ref_raw_ = 0, ref_comp_ = 0;
	bool from_rmc_ = false;
	double prev_gga_t_ = NAN, prev_lat_ = 0, prev_lon_ = 0;
};
}  // namespace

NoTruthReport compareHeadingsWithoutTruth(const std::string& path, const Calibration& cal, const NoTruthOptions& options)
{
	Analysis a(path, cal, options);
	return a.run();
}

}  // namespace mrpt_fog::heading
