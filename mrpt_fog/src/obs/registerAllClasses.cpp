/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/core/initializer.h>
#include <mrpt/obs/registerAllClasses.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/registerAllClasses.h>

MRPT_INITIALIZER(registerAllClasses_mrpt_fog_initializer)
{
	using namespace mrpt::rtti;
	registerClass(CLASS_ID(mrpt_fog::CObservationFOG));
}

void mrpt_fog::registerAllClasses_mrpt_fog()
{
	mrpt::obs::registerAllClasses_mrpt_obs();
	mrpt::rtti::registerClass(CLASS_ID(mrpt_fog::CObservationFOG));
}
