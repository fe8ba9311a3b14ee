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
	// Well-formed per Unicode Table 3-7, not just lead + continuation bytes:
	EXPECT_EQ(firstInvalidUtf8("a\xe0\x92\x96"), 1u);  // overlong 3-byte form (E0 needs A0..BF)
	EXPECT_EQ(firstInvalidUtf8("\xed\xa0\x80"), 0u);  // UTF-16 surrogate U+D800
	EXPECT_EQ(firstInvalidUtf8("\xf4\x90\x80\x80"), 0u);  // above U+10FFFF
	EXPECT_EQ(firstInvalidUtf8("\xf0\x8f\xbf\xbf"), 0u);  // overlong 4-byte form
	EXPECT_EQ(firstInvalidUtf8("\xf5\x80\x80\x80"), 0u);
	// the boundaries themselves are valid
	EXPECT_EQ(firstInvalidUtf8("\xe0\xa0\x80 \xed\x9f\xbf \xee\x80\x80 \xf0\x90\x80\x80 \xf4\x8f\xbf\xbf"), std::string::npos);
}
