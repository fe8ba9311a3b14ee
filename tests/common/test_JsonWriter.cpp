/* Tests of mrpt_fog::JsonValue (the --json output of every program). */
#include <gtest/gtest.h>
#include <mrpt_fog/common/JsonWriter.h>

#include <cmath>

using namespace mrpt_fog;

TEST(JsonValue, NestedObjectsKeepInsertionOrder)
{
	JsonValue j;
	j["raw"]["stability_dph"] = 0.114857;
	j["raw"]["range_dph"] = 0.5082;
	j["tau_s"] = 100;
	j["name"] = "a\"b\n";
	EXPECT_EQ(j.dump(),
			  "{\n  \"raw\": {\n    \"stability_dph\": 0.114857,\n    \"range_dph\": 0.5082\n  },\n"
			  "  \"tau_s\": 100,\n  \"name\": \"a\\\"b\\n\"\n}\n");
}

TEST(JsonValue, NaNBecomesNullAndArraysWork)
{
	JsonValue j = JsonValue::array();
	j.push_back(std::nan(""));
	j.push_back(true);
	j.push_back(JsonValue::object());
	EXPECT_EQ(j.dump(), "[\n  null,\n  true,\n  {}\n]\n");
}
