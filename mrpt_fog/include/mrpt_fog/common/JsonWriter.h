/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file JsonWriter.h
 * A tiny JSON document builder for the programs' `--json FILE` output (stable keys, numbers
 * printed with 10 significant digits; NaN/inf are written as null since JSON has no NaN).
 *
 *   JsonValue j = JsonValue::object();
 *   j["raw"]["stability_dph"] = 0.114;
 *   j["tau_s"] = 100;
 *   writeTextFileAtomically("out.json", j.dump());
 */

#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog
{
class JsonValue
{
   public:
	enum class Kind
	{
		Null,
		Bool,
		Number,
		String,
		Array,
		Object
	};

	JsonValue() = default;
	JsonValue(double v) : kind_(Kind::Number), number_(v) {}
	JsonValue(int v) : kind_(Kind::Number), number_(v) {}
	JsonValue(long v) : kind_(Kind::Number), number_(static_cast<double>(v)) {}
	JsonValue(unsigned long v) : kind_(Kind::Number), number_(static_cast<double>(v)) {}
	JsonValue(unsigned v) : kind_(Kind::Number), number_(v) {}
	JsonValue(bool v) : kind_(Kind::Bool), bool_(v) {}
	JsonValue(const char* v) : kind_(Kind::String), string_(v) {}
	JsonValue(std::string v) : kind_(Kind::String), string_(std::move(v)) {}

	static JsonValue object();
	/** An object of the given members, in this order: JsonValue::object({{"id", id}, {"rms_dph", r}}). */
	static JsonValue object(std::initializer_list<std::pair<std::string, JsonValue>> members);
	static JsonValue array();
	/** An array of the given items: JsonValue::array({low, high}). */
	static JsonValue array(std::initializer_list<JsonValue> items);
	/** An array of each element of a container (strings, numbers, ...). */
	template <class Container>
	static JsonValue arrayOf(const Container& items)
	{
		JsonValue a = array();
		for (const auto& x : items) a.push_back(JsonValue(x));
		return a;
	}
	/** An array of toJson(x) for each element x of a container, in order. */
	template <class Container, class ToJson>
	static JsonValue arrayOf(const Container& items, ToJson&& toJson)
	{
		JsonValue a = array();
		for (const auto& x : items) a.push_back(toJson(x));
		return a;
	}

	/** Object member (created on first use; a Null value becomes an object). Keys keep
	 * insertion order in the output. */
	JsonValue& operator[](const std::string& key);
	/** Appends to an array (a Null value becomes an array). */
	void push_back(JsonValue v);

	Kind kind() const { return kind_; }
	/** Pretty-printed JSON text with 2-space indentation and a final newline. */
	std::string dump() const;

   private:
	void dumpTo(std::string& out, int indent) const;
	Kind kind_ = Kind::Null;
	double number_ = 0;
	bool bool_ = false;
	std::string string_;
	std::vector<std::pair<std::string, JsonValue>> members_;
	std::vector<JsonValue> items_;
};

}  // namespace mrpt_fog
