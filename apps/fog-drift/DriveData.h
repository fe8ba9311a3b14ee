/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file DriveData.h
 * The drive in memory and its truth-aligned dead reckoning, as fog-drift names them (the
 * library's: heading/DriveLog.h, heading/TruthAlignedDeadReckoning.h). */

#include <mrpt_fog_heading/DriveLog.h>
#include <mrpt_fog_heading/TruthAlignedDeadReckoning.h>

namespace mrpt_fog::drift
{
using heading::absoluteTimes;
using heading::deadReckonVariant;
using heading::DriveData;
using heading::DriveLabels;
using heading::driveLatitude;
using heading::HeadingOptions;
using heading::NoTruthError;
using heading::OdometryPoses;
using heading::pitchOf;
using heading::readDrive;
using heading::rollOf;
using heading::VariantResult;
}  // namespace mrpt_fog::drift
