/* Tests of firstInvalidUtf8 against hand-made byte strings (RFC 3629 forms). */
#include <gtest/gtest.h>
#include <mrpt_fog/common/Utf8.h>

using namespace mrpt_fog;

TEST(Utf8, ValidTextPasses)
{
	EXPECT_EQ(firstInvalidUtf8("plain ascii: 25 C\n"), std::string::npos);
	EXPECT_EQ(firstInvalidUtf8("25 \xc2\xb0" "C, \xe2\x80\x94, \xf0\x9f\x8c\xa1"), std::string::npos);  // degree, em dash, emoji
	EXPECT_EQ(firstInvalidUtf8(""), std::string::npos);
}

TEST(Utf8, InvalidBytesAreLocated)
{
	EXPECT_EQ(firstInvalidUtf8("%\xd5\n"), 1u);  // lead byte followed by a non-continuation
	EXPECT_EQ(firstInvalidUtf8("ab\x80"), 2u);  // stray continuation byte
	EXPECT_EQ(firstInvalidUtf8("\xc0\xaf"), 0u);  // overlong '/'
	EXPECT_EQ(firstInvalidUtf8("x\xe2\x82"), 1u);  // truncated 3-byte sequence
	EXPECT_EQ(firstInvalidUtf8("\xff"), 0u);
}
