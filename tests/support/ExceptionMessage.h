/* mrpt_fog test support: the message of the exception a call must throw. */
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <string>

namespace fogtest
{
/** Runs f; returns the message of the exception of type E it must throw ("" and a test failure
 * when it throws nothing, the message and a failure when it throws another type). */
template <class E, class F>
std::string messageOf(F&& f)
{
	try
	{
		f();
	}
	catch (const E& e)
	{
		return e.what();
	}
	catch (const std::exception& e)
	{
		ADD_FAILURE() << "expected another exception type, got: " << e.what();
		return e.what();
	}
	ADD_FAILURE() << "nothing thrown";
	return {};
}
}  // namespace fogtest
