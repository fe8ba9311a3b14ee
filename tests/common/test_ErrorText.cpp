/* Tests of oneLineErrorMessage: MRPT's multi-line exception texts become one readable line. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/ErrorText.h>

using namespace mrpt_fog;

TEST(ErrorText, MrptExceptionKeepsMessageOnly)
{
	const std::string what =
		"==== MRPT exception ====\nMessage:  Trying to read from a non-scalar.\nLocation: /usr/include/x.h:12\n"
		"Call stack backtrace:\n[0 ] 0x7f89 foo\n";
	EXPECT_EQ(oneLineErrorMessage(what), "Trying to read from a non-scalar.");
}

TEST(ErrorText, PlainTextLinesJoined)
{
	EXPECT_EQ(oneLineErrorMessage("first\n  second  \n\n"), "first; second");
	EXPECT_EQ(oneLineErrorMessage(""), "unknown error");
}
