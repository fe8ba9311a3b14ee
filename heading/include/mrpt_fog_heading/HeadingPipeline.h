/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file HeadingPipeline.h
 * A vehicle's heading and dead-reckoned pose from its FOG and wheel odometry, observation by
 * observation, in memory that does not grow with the drive:
 *
 *   FOG sample (CObservationFOG, or the stock CObservationIMU + CObservationRawDAQ pair)
 *     -> thermistor screening (ThermistorHealth)            [with a calibration]
 *     -> thermal compensation (Compensator, causal)         [with a calibration]
 *     -> rate correction (RateCorrection.h, optional: e.g. an in-field bias estimate)
 *     -> + the calibration's Earth rate (CalibrationEarthRate.h, the Earth-rate rule)
 *     -> strapdown heading (nav::StrapdownAttitude, vertical gyro, the drive's Earth rate
 *        removed)
 *   wheel odometry (CObservationOdometry) -> distance per interval
 *     -> dead reckoning (nav::deadReckonStep2D) with the FOG heading at each odometry time.
 *
 * Alignment: by default at the first odometry sample, to the wheel odometry's own pose (the
 * output is in the odometry's frame: what MRPT's localization expects of an odometry); or at a
 * time of the caller's choice (align(), e.g. from a truth or a GNSS fix), and again later
 * (realign(), e.g. from the truth at a turn-on). FOG samples before the alignment are
 * compensated (the compensator needs their history) but not integrated.
 *
 * Gyro off (obs/GyroPower.h: power 0): no rate to integrate. The poses inside a gyro-off
 * stretch take the wheels' heading change (HeadingSource::Wheels); at the turn-on the heading
 * goes on from the last pose's (the wheels' rotation between the last odometry of the stretch
 * and the turn-on is not seen: at most one odometry interval). Poses after the gyro's last
 * sample (finish()) are also the wheels'.
 *
 * Streaming: a pose is final once a FOG sample at or after its time has come (the heading is
 * interpolated between the two attitudes around it); popPose() gives the final poses in order.
 * Memory: the attitudes since the oldest pose still waiting, at most max_odometry_lag_s of them.
 *
 * Times: absolute [s] (mrpt::Clock::toDouble of the timestamps); FogSample::time_s is relative
 * to the header's epoch_s, as FogLogReader gives it. Rates deg/h, angles rad, lengths m.
 * Bad input throws std::runtime_error naming the time: a FOG time not increasing, a powered
 * sample without a finite rate, a FOG layout other than the header's, an odometry that arrives
 * more than max_odometry_lag_s after the FOG samples past its time. An odometry sample at or
 * before the previous one's time is skipped (counted). */

#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog/model/ThermistorHealth.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>
#include <mrpt_fog_heading/RateCorrection.h>
#include <mrpt_fog_heading/StandstillCorrection.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace mrpt_fog::heading
{
/** How the pipeline gets its initial heading and position. */
enum class Alignment
{
	AtFirstOdometry,  //!< the first odometry sample's pose (default)
	ByCaller  //!< align() (odometry before it gives no pose)
};

struct PipelineOptions
{
	/** The drive's latitude [deg] (required; e.g. driveLatitude(header)). */
	double latitude_deg = std::numeric_limits<double>::quiet_NaN();
	/** How a rate sample relates to its interval (digital FOGs and fog-sim: IntervalAverage). */
	nav::RateSampling sampling = nav::RateSampling::IntervalAverage;
	bool screen_thermistors = true;  //!< ThermistorHealth before the compensator
	CalibrationEarthRateOptions earth;  //!< the calibration latitude's override
	Alignment alignment = Alignment::AtFirstOdometry;
	/** How long an odometry sample may arrive after the FOG samples past its time [s]. */
	double max_odometry_lag_s = 10.0;
	/** Standstill updates of the turn-on bias offset (StandstillCorrection.h), installed as the
	 * rate correction when there is a calibration; false: none. setRateCorrection() replaces it. */
	bool field_refinement = true;
	StandstillCorrectionOptions field;
	/** What the calibration learned in the field (FieldOffset.h, fog-refine's section of the
	 * calibration file, loadFieldOffset()): its offset at each sample's date is subtracted from
	 * the compensated rate (with a calibration only), and its 1-sigma at the first sample adds to
	 * the thermal model's in the standstill updates' prior. */
	std::optional<FieldOffset> field_offset;
};

/** One FOG sample through the pipeline. */
struct RateStep
{
	double t_s = 0.0;  //!< absolute [s]
	double raw_dph = std::numeric_limits<double>::quiet_NaN();  //!< the gyro's output (NaN while off)
	/** thermal model applied, and the calibration's field offset (PipelineOptions::field_offset)
	 * removed (= raw without a calibration) */
	double compensated_dph = std::numeric_limits<double>::quiet_NaN();
	double corrected_dph = std::numeric_limits<double>::quiet_NaN();  //!< after the RateCorrection (= compensated without one)
	double integrated_dph = std::numeric_limits<double>::quiet_NaN();  //!< corrected + the calibration's Earth rate: what the strapdown takes
	/** the yaw rate against the local-level frame [rad/s]: integrated minus the drive's vertical
	 * Earth rate (what an MRPT IMU observation of the vehicle's yaw rate holds) */
	double yaw_rate_rad_s = std::numeric_limits<double>::quiet_NaN();
	double heading_rad = std::numeric_limits<double>::quiet_NaN();  //!< after this sample (NaN before the alignment)
	std::uint8_t compensation_flags = 0;  //!< CompensationFlag bits
	bool gyro_on = true;
	bool turn_on = false;
	bool integrated = false;  //!< this sample moved the heading
};

/** What gave a pose's heading. */
enum class HeadingSource
{
	Gyro,  //!< the FOG heading
	Wheels  //!< the wheels' heading change (gyro off, or after the gyro's last sample)
};

struct DeadReckonedPose
{
	double t_s = 0.0;  //!< the odometry sample's time [s]
	double x_m = 0.0, y_m = 0.0, heading_rad = 0.0;  //!< heading in (-pi, pi]
	HeadingSource source = HeadingSource::Gyro;
	WheelOdometry wheel;  //!< the odometry sample it was made from
};

struct PipelineCounters
{
	std::size_t fog_samples = 0, integrated_samples = 0, gyro_off_samples = 0, turn_ons = 0;
	std::size_t odometry_samples = 0, odometry_skipped = 0;  //!< skipped: time not after the previous one
	std::size_t poses = 0, wheel_poses = 0;  //!< poses given, of which with the wheels' heading
};

class HeadingPipeline
{
   public:
	/** header: the FOG's layout and metadata (FogLogReader::header(), or headerOf() of its first
	 * observation); cal: the z-axis calibration, or null for the raw rate. Throws
	 * std::invalid_argument on a latitude outside [-90, 90], a header without a z axis, or a
	 * calibration that does not fit the layout. */
	HeadingPipeline(const FogSeries& header, const PipelineOptions& options, const Calibration* cal = nullptr);
	~HeadingPipeline();
	HeadingPipeline(const HeadingPipeline&) = delete;
	HeadingPipeline& operator=(const HeadingPipeline&) = delete;

	/** The layout of a FOG observation as a header (no samples; epoch_s its whole second). */
	static FogSeries headerOf(const CObservationFOG& first);

	/** The correction stage (RateCorrection.h); null removes it. Set it before the first sample. */
	void setRateCorrection(std::shared_ptr<RateCorrection> correction) { correction_ = std::move(correction); }
	/** The correction stage (null: none). */
	RateCorrection* rateCorrection() const { return correction_.get(); }

	/** One FOG sample (FogSample::time_s relative to the header's epoch). */
	const RateStep& addFog(const FogSample& sample);
	/** One FOG observation (its layout must be the header's). */
	const RateStep& addFog(const CObservationFOG& obs);
	/** The stock pair fog-compensate and FogSeries' stock form write: IMU_WZ [rad/s] (the raw
	 * rate), and the thermistors in the header's order from the RawDAQ's AIN_double (null or
	 * missing: dropouts). No power state (never gyro-off). */
	const RateStep& addFog(const mrpt::obs::CObservationIMU& imu, const mrpt::obs::CObservationRawDAQ* thermistors);

	/** One wheel odometry sample: cumulative pose at absolute time t_s. */
	void addOdometry(double t_s, double x_m, double y_m, double phi_rad);
	void addOdometry(const mrpt::obs::CObservationOdometry& odo);

	/** Initial heading [rad] at t_s [s], and the position [m] the first odometry sample at or
	 * after t_s starts from (Alignment::ByCaller; also allowed once with AtFirstOdometry before
	 * any odometry). Throws when already aligned. */
	void align(double t_s, double heading_rad, double x_m, double y_m);

	/** A new alignment at t_s [s] from an external reference (e.g. the truth or a GNSS heading at
	 * the turn-on after a gyro-off stretch), in place of the turn-on rule: the poses still waiting
	 * are made final first, as finish() makes them; then, as align(), the heading restarts at t_s
	 * from heading_rad and the dead reckoning from (x_m, y_m) at the first odometry sample given
	 * after this call at or after t_s. Before any alignment it is align(). Throws when t_s is
	 * before the last FOG sample's time. */
	void realign(double t_s, double heading_rad, double x_m, double y_m);

	/** The next final pose, in time order; false when none is ready. */
	bool popPose(DeadReckonedPose& pose);
	/** The end of the stream: the poses still waiting are made final (with the wheels' heading
	 * past the gyro's last sample). */
	void finish();

	bool aligned() const { return aligned_; }
	double heading_rad() const;  //!< the strapdown heading now (NaN before the alignment)
	/** The strapdown attitude now (body to local level; after the last integrated sample, or the
	 * alignment's; meaningless before the alignment): for a caller that interpolates the heading
	 * between samples itself (e.g. a comparison with a truth at the truth's times). */
	Eigen::Quaterniond attitude() const { return att_.attitude(); }
	const RateStep& lastStep() const { return step_; }
	const PipelineCounters& counters() const { return counters_; }
	/** The compensator's counters (null without a calibration). */
	const CompensationCounters* compensationCounters() const;
	/** The thermistor screening's counters per thermistor (empty without screening). */
	std::vector<ThermistorHealthCounters> screeningCounters() const;
	const CalibrationEarthRate& earthRate() const { return earth_; }
	/** The drive's vertical Earth rate [deg/h], removed by the strapdown. */
	double driveEarthRate_dph() const { return drive_earth_dph_; }
	const FogSeries& header() const { return header_; }

   private:
	struct Att
	{
		double t_s;
		Eigen::Quaterniond q;
	};
	const RateStep& step(double t_abs_s, double time_s, double raw_dph, const double* temp_C, std::size_t n_temp,
						 double field_uT, double power);
	double yawAt(double t_s) const;
	void resolve();
	void emit(const WheelOdometry& w, double heading_rad, HeadingSource source);
	void prune();

	FogSeries header_;
	PipelineOptions options_;
	std::optional<Calibration> cal_;
	std::unique_ptr<Compensator> compensator_;
	std::unique_ptr<ThermistorHealth> health_;
	std::shared_ptr<RateCorrection> correction_;
	CalibrationEarthRate earth_;
	double drive_earth_dph_ = 0.0, thermal_sigma_dph_ = 0.0, sigma_dph_ = std::numeric_limits<double>::quiet_NaN();
	nav::StrapdownAttitude att_;
	std::deque<Att> track_;
	std::vector<double> temps_;
	RateStep step_;
	PipelineCounters counters_;
	bool any_fog_ = false, aligned_ = false, gyro_off_ = false, restarted_ = false, finished_ = false;
	double last_fog_t_ = 0.0, prev_power_ = std::numeric_limits<double>::quiet_NaN(), t0_ = 0.0;
	double start_x_m_ = 0.0, start_y_m_ = 0.0;
	bool start_given_ = false;
	std::optional<WheelOdometry> last_odo_;
	std::deque<WheelOdometry> pending_;
	std::optional<DeadReckonedPose> last_pose_;
	std::deque<DeadReckonedPose> ready_;
};

/** The drive's latitude [deg] from a FOG header's metadata (latitude_deg, or
 * device.latitude_deg as fog-sim writes it); nullopt when absent or not in [-90, 90]. */
std::optional<double> latitudeOf(const FogSeries& header);

}  // namespace mrpt_fog::heading
