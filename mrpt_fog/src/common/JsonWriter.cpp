/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/JsonWriter.h>

#include <cmath>
#include <cstdio>

namespace mrpt_fog
{
JsonValue JsonValue::object()
{
	JsonValue v;
	v.kind_ = Kind::Object;
	return v;
}

JsonValue JsonValue::object(std::initializer_list<std::pair<std::string, JsonValue>> members)
{
	JsonValue v = object();
	v.members_.assign(members.begin(), members.end());
	return v;
}

JsonValue JsonValue::array()
{
	JsonValue v;
	v.kind_ = Kind::Array;
	return v;
}

JsonValue JsonValue::array(std::initializer_list<JsonValue> items)
{
	JsonValue v = array();
	v.items_.assign(items.begin(), items.end());
	return v;
}

JsonValue& JsonValue::operator[](const std::string& key)
{
	if (kind_ == Kind::Null) kind_ = Kind::Object;
	for (auto& kv : members_)
		if (kv.first == key) return kv.second;
	members_.emplace_back(key, JsonValue());
	return members_.back().second;
}

void JsonValue::push_back(JsonValue v)
{
	if (kind_ == Kind::Null) kind_ = Kind::Array;
	items_.push_back(std::move(v));
}

static void appendEscaped(std::string& out, const std::string& s)
{
	out += '"';
	for (unsigned char c : s)
	{
		switch (c)
		{
			case '"': out += "\\\""; break;
			case '\\': out += "\\\\"; break;
			case '\n': out += "\\n"; break;
			case '\r': out += "\\r"; break;
			case '\t': out += "\\t"; break;
			default:
				if (c < 0x20)
				{
					char buf[8];
					std::snprintf(buf, sizeof(buf), "\\u%04x", c);
					out += buf;
				}
				else
					out += static_cast<char>(c);
		}
	}
	out += '"';
}

namespace
{
/** An array or object: `open`, one indented line per element (writeElement(i)), `close`;
 * "[]" / "{}" when empty. */
template <class WriteElement>
void appendContainer(std::string& out, int indent, std::size_t count, char open, char close, WriteElement writeElement)
{
	if (count == 0)
	{
		out += open;
		out += close;
		return;
	}
	const std::string pad(static_cast<size_t>(indent + 2), ' ');
	out += open;
	out += '\n';
	for (size_t i = 0; i < count; i++)
	{
		out += pad;
		writeElement(i);
		out += i + 1 < count ? ",\n" : "\n";
	}
	out += std::string(static_cast<size_t>(indent), ' ');
	out += close;
}
}  // namespace

void JsonValue::dumpTo(std::string& out, int indent) const
{
	switch (kind_)
	{
		case Kind::Null: out += "null"; break;
		case Kind::Bool: out += bool_ ? "true" : "false"; break;
		case Kind::Number:
		{
			if (!std::isfinite(number_))
			{
				out += "null";
				break;
			}
			char buf[32];
			std::snprintf(buf, sizeof(buf), "%.10g", number_);
			out += buf;
			break;
		}
		case Kind::String: appendEscaped(out, string_); break;
		case Kind::Array:
			appendContainer(out, indent, items_.size(), '[', ']', [&](size_t i) { items_[i].dumpTo(out, indent + 2); });
			break;
		case Kind::Object:
			appendContainer(out, indent, members_.size(), '{', '}', [&](size_t i) {
				appendEscaped(out, members_[i].first);
				out += ": ";
				members_[i].second.dumpTo(out, indent + 2);
			});
			break;
	}
}

std::string JsonValue::dump() const
{
	std::string out;
	dumpTo(out, 0);
	out += '\n';
	return out;
}

}  // namespace mrpt_fog
