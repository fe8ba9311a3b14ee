/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file EnumNames.h
 * The spelling of a closed set of choices, written once as a table that both directions read:
 *
 *   constexpr EnumName<CoilSide> kCoilSides[] = {{CoilSide::Inner, "inner"}, ...};
 *   const char* toString(CoilSide s) { return nameIn(kCoilSides, s, "other"); }
 *   if (const auto s = valueIn(kCoilSides, text)) return *s;  // else throw, naming the choices
 */

#include <cstddef>
#include <optional>
#include <string>

namespace mrpt_fog
{
template <class E>
struct EnumName
{
	E value;
	const char* name;
};

/** The name of `value` in `names`, or `fallback` for a value the table does not hold. */
template <class E, std::size_t N>
const char* nameIn(const EnumName<E> (&names)[N], E value, const char* fallback)
{
	for (const auto& n : names)
		if (n.value == value) return n.name;
	return fallback;
}

/** The value spelled exactly `text` in `names`, or std::nullopt. */
template <class E, std::size_t N>
std::optional<E> valueIn(const EnumName<E> (&names)[N], const std::string& text)
{
	for (const auto& n : names)
		if (text == n.name) return n.value;
	return std::nullopt;
}
}  // namespace mrpt_fog
