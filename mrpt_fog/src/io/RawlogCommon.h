/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/* Internal to the io room: MRPT time ticks shared by the rawlog reader and writer (exception
 * texts on one line: common/ErrorText.h). */

#include <mrpt/core/Clock.h>

#include <cstdint>
#include <string>

namespace mrpt_fog::io::detail
{
/** MRPT timestamps are 100 ns ticks. */
constexpr double kTicksPerSecond = 1e7;

inline int64_t ticksOf(mrpt::Clock::time_point t) { return t.time_since_epoch().count(); }
inline mrpt::Clock::time_point fromTicks(int64_t ticks) { return mrpt::Clock::time_point(mrpt::Clock::duration(ticks)); }

}  // namespace mrpt_fog::io::detail
