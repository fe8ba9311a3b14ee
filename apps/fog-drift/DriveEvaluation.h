/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file DriveEvaluation.h
 * One drive through fog-drift: read it, compensate its FOG with the calibration (if any), dead
 * reckon each gyro variant (raw, compensated, ideal), compare with the truth (DriftReport) and
 * compute the navigation figures of each variant (HeadingFigures: RMS, max, final heading
 * error, drift between turns, turn scale factor). And the summary over several drives
 * (median, quartiles, min, max of each figure and ratio). */

#include "DriveData.h"
#include "FieldRefinement.h"
#include "GyroOff.h"

#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog_nav/DriftReport.h>
#include <mrpt_fog_nav/HeadingFigures.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::drift
{
/** Which dead-reckoned trajectories evaluateDrive keeps after computing their figures (each
 * is ~80 B per sample): every one (--plots), the one --odometry-out writes (compensated, else
 * raw), or none. */
enum class KeptTrajectories
{
	All,
	ForOdometry,
	None
};

struct DriveSettings
{
	KeptTrajectories keep_trajectories = KeptTrajectories::All;
	std::string cal_path;  //!< "" = no compensated variant
	LogReadOptions read_options;  //!< how the drive log is read (its unit notices)
	std::optional<double> latitude_deg;  //!< override of the drive's metadata
	std::optional<double> cal_latitude_deg;  //!< override of the calibration's latitude
	bool cal_no_earth_rate = false;  //!< the calibration's bias holds no Earth rate
	bool screen_thermistors = true;
	bool quiet = false;  //!< no progress line on stderr while a drive is read
	/** The per-sample drift series are wanted (--csv): held in DriftReport's t_s and errors when
	 * the drive is held in memory, spilled to temporary files (DriveEvaluation::spilled) when it
	 * is streamed. */
	bool keep_series = false;
	/** Hold the drive in memory even when nothing asks for it (--in-memory: the reference the
	 * streaming evaluation is tested against). */
	bool in_memory = false;
	HeadingOptions heading;  //!< latitude_deg filled per drive
	DriveLabels labels;  //!< --fog-label, --odometry-label, --truth-label
	nav::HeadingFigureOptions figures;
	/** Standstill updates of the compensated gyro's bias offset (on by default; the compensated
	 * variant of a single-axis FOG only). */
	FieldRefinementSettings refinement;
};

/** Attitude errors of a triad variant against the truth (3-D strapdown) [deg]. */
struct AttitudeFigures
{
	double roll_error_rms_deg = 0, roll_error_max_deg = 0, roll_error_final_deg = 0;
	double pitch_error_rms_deg = 0, pitch_error_max_deg = 0, pitch_error_final_deg = 0;
};

/** The per-sample drift series of a streamed evaluation with DriveSettings::keep_series (--csv):
 * in temporary files (common/RowSpill.h), not in memory. */
struct SpilledSeries
{
	RowSpill truth{2};  //!< every truth pose in order: t [s, absolute], yaw [rad]
	/** per variant of the report, in its order: t [s], heading error [deg], position error [m]
	 * at the truth times it was compared at */
	std::vector<std::unique_ptr<RowSpill>> variants;
	/** --odometry-out (DriveSettings::keep_trajectories ForOdometry): the odometry variant's
	 * (compensated, else raw) dead-reckoned poses (t, x, y, yaw) and integrated gyro rates
	 * (t, yaw rate without the Earth's [rad/s]), of the powered spans the figures cover */
	std::string odometry_variant;
	RowSpill odometry_poses{4};
	RowSpill odometry_rates{2};
};

struct DriveEvaluation
{
	std::string input;
	/** After evaluateDrive: the truth, and the FOG's label, epoch and metadata; the per-sample
	 * FOG, ideal FOG and odometry are released once dead-reckoned (memory). */
	DriveData drive;
	double latitude_deg = 0.0;
	double calibration_earth_rate_dph = 0.0;  //!< vertical Earth rate the calibration's bias held
	std::string calibration_latitude_source;  //!< "option", "calibration" or "drive"
	/** An option that overrides a different value in the drive's or the calibration's metadata
	 * (--latitude-deg, --cal-latitude-deg), one sentence each: printed as notes and in --json. */
	std::vector<std::string> option_conflicts;
	/** A calibrated axis has a magnetic section (MagneticModel.h), and the warning when the drive
	 * lacked the field on some samples (apps/common/FieldWarning.h; "" when it had it throughout). */
	bool magnetic_term = false;
	std::string field_warning;
	/** The in-field refinement of the compensated variant (FieldRefinement.h). */
	FieldRefinementResult refinement;
	std::vector<nav::NamedTrajectory> variants;  //!< names; trajectories as DriveSettings::keep_trajectories says (else empty)
	std::vector<VariantResult> results;  //!< same order as variants (their trajectories moved there)
	nav::DriftReport report;
	nav::DriveSegments segments;
	std::map<std::string, nav::HeadingFigures> figures;  //!< by variant name
	/** The FOG's gyro-off stretches (GyroOff.h; empty without power 0 rows): the heading is not
	 * observable there; each powered span is navigated alone, re-aligned from the truth at its
	 * start, and the figures above are those of the powered spans. */
	std::vector<GyroOffStretch> gyro_off;
	std::size_t powered_spans = 1;  //!< powered spans of the FOG (1 without gyro-off stretches)
	std::size_t powered_spans_navigated = 1;  //!< of them, long enough to navigate (the raw gyro's)
	/** Triad FOG (x, y, z) and a calibration of all three axes (or none): the 3-D strapdown
	 * (heading = its yaw), attitude figures and per-axis rate errors below. */
	bool three_axis = false;
	std::string three_axis_note;  //!< why a triad log was not run in 3-D ("" otherwise)
	std::map<std::string, AttitudeFigures> attitude;  //!< by variant name (three_axis only)
	/** Per axis x, y, z: RMS of the 100 s block means of (variant - ideal) over the powered
	 * samples [deg/h]: the thermal error left on each axis (raw, compensated; three_axis only). */
	std::map<std::string, std::array<double, 3>> rate_error_rms_dph;
	/** Streamed with DriveSettings::keep_series or keep_trajectories ForOdometry: the per-sample
	 * series (DriftReport's and the trajectories are empty). */
	std::shared_ptr<SpilledSeries> spilled;
};

/** The latitude the drive is integrated at (--latitude-deg, else the drive's metadata, else an
 * error naming `path`) into e.latitude_deg, and the heading options with it. */
HeadingOptions headingOptionsFor(DriveEvaluation& e, const std::string& path, const DriveSettings& settings);

/** Throws std::runtime_error naming the file on any problem. Streams the drive (StreamingDrive.h:
 * memory that does not grow with it) when canStream(settings) and the FOG is single-axis; holds
 * it in memory otherwise. */
DriveEvaluation evaluateDrive(const std::string& path, const DriveSettings& settings);

/** The vertical Earth rate the z calibration's bias holds at the calibration's latitude
 * (option, file, else the drive's: e.latitude_deg) into e.calibration_earth_rate_dph and
 * e.calibration_latitude_source; returns whether the bias holds it. */
bool noteCalibrationEarthRate(DriveEvaluation& e, const DriveSettings& settings, const Calibration& zcal);

/** Appends the drift series of a later powered span to `into` (the maxima over both, the
 * finals of `part`; `distance_m`: the drive's, for the percentages). */
void appendDriftSeries(nav::DriftSeries& into, nav::DriftSeries&& part, double distance_m);

/** Median, quartiles (linear interpolation between order statistics) and extremes. */
struct Spread
{
	std::size_t n = 0;
	double median = 0, q1 = 0, q3 = 0, min = 0, max = 0;
};
/** Over the finite values; n = 0 when there is none. */
Spread spreadOf(std::vector<double> values);

/** The figure names and ratios summarised over drives, per drive (NaN when a variant is absent). */
std::map<std::string, double> driveFigureTable(const DriveEvaluation& e);

}  // namespace mrpt_fog::drift
