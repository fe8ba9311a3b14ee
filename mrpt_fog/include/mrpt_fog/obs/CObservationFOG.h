/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CSerializable.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <array>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** One sample of a fiber-optic gyroscope (FOG) with thermistors glued around its fiber coil.
 *
 * Stores what a FOG engineer logs: the rate of 1, 2 or 3 sensitive axes in deg/h (raw gyro
 * output, bias included), N thermistor readings in degC (N = 0..65535) each with its metadata
 * (name, inner/outer side, angle on the coil [deg]) and a validity flag (a dropout is not
 * 0 degC), and optional lab fields (applied table rate [deg/h], axial magnetic field [uT],
 * power state). Accessors in rad/s are provided for navigation code.
 *
 * For stock MRPT tools, toIMU() gives a CObservationIMU (IMU_WX/WY/WZ in rad/s, mean valid
 * temperature in IMU_TEMPERATURE) and toRawDAQ() a CObservationRawDAQ (thermistors in
 * AIN_double, degC, NaN for a dropout).
 *
 * Serialization is versioned (version 0 is the current format); unknown versions throw.
 */
class CObservationFOG : public mrpt::obs::CObservation
{
	DEFINE_SERIALIZABLE(CObservationFOG, mrpt_fog)

   public:
	CObservationFOG() = default;

	/** Pose of the gyro on the vehicle/robot (sensitive axes = this frame's axes). */
	mrpt::poses::CPose3D sensorPose;

	/** Which sensitive axes (x, y, z of sensorPose) this gyro has. */
	std::array<bool, 3> hasAxis{{false, false, true}};
	/** Gyro output per axis [deg/h] (meaningful only where hasAxis); NaN = no gyro sample,
	 * allowed only with the power off (hasPower && !powerOn). */
	std::array<double, 3> rate_dph{{0, 0, 0}};

	/** Metadata of each thermistor (same order as temp_C). */
	std::vector<ThermistorInfo> thermistors;
	/** Thermistor readings [degC]; read through temperature_C() which honours tempValid. */
	std::vector<double> temp_C;
	/** Validity of each reading (false = dropout: the value in temp_C is meaningless). */
	std::vector<bool> tempValid;

	bool hasTableRate = false;
	double tableRate_dph = 0;  //!< applied rate-table rotation about the sensitive axis [deg/h]
	bool hasField = false;
	double field_uT = 0;  //!< applied axial magnetic field [uT]
	bool hasPower = false;
	bool powerOn = true;  //!< gyro power state (only meaningful with hasPower)

	/** Rate of an axis [rad/s]; throws std::out_of_range if the axis is absent. */
	double rate_rad_s(GyroAxis axis) const;
	/** Rate of an axis [deg/h]; throws std::out_of_range if the axis is absent. */
	double rateOf_dph(GyroAxis axis) const;
	/** Sets an axis' rate [deg/h] and marks the axis present. */
	void setRate_dph(GyroAxis axis, double value_dph);

	/** Reading of thermistor i [degC], NaN when invalid (dropout). */
	double temperature_C(std::size_t i) const;
	/** Appends a thermistor and its reading; NaN or valid=false records a dropout. */
	void addThermistor(const ThermistorInfo& info, double value_C, bool valid = true);
	/** Mean of the valid thermistor readings [degC], NaN when none is valid. */
	double meanTemperature_C() const;

	/** Checks internal consistency (sizes, at least one axis, finite rates: NaN only with the
	 * power off); throws
	 * std::invalid_argument with the reason. */
	void validate() const;

	/** Stock MRPT IMU observation (rates rad/s in IMU_WX/WY/WZ, mean temperature degC). */
	mrpt::obs::CObservationIMU::Ptr toIMU() const;
	/** Stock MRPT DAQ observation with the thermistor channels in AIN_double [degC]. */
	mrpt::obs::CObservationRawDAQ::Ptr toRawDAQ() const;

	// See base class docs
	void getSensorPose(mrpt::poses::CPose3D& out_sensorPose) const override { out_sensorPose = sensorPose; }
	void setSensorPose(const mrpt::poses::CPose3D& newSensorPose) override { sensorPose = newSensorPose; }
	void getDescriptionAsText(std::ostream& o) const override;
	bool exportTxtSupported() const override { return true; }
	/** Columns: rate_x_dph rate_y_dph rate_z_dph (NaN where absent), one temp_<name>_C per
	 * thermistor (NaN for a dropout), table_rate_dph field_uT power (NaN where absent). */
	std::string exportTxtHeader() const override;
	std::string exportTxtDataRow() const override;
};

}  // namespace mrpt_fog
