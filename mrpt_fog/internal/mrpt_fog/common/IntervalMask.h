/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file IntervalMask.h
 * One flag per row (e.g. "usable sample") for runs longer than memory: kept as the sorted list of
 * [begin, end) intervals of set rows, so a log whose usable samples form a few long stretches (a
 * clean chamber run: one) costs a few words whatever its length, where one bit per sample grows
 * with it (3.6 MB at 28.8 M samples). When the intervals would take more than one bit per row
 * (a flag that flips very often), the mask switches to a bit vector: never more than that.
 *
 *   IntervalMask ok;
 *   ok.assign(n, true);
 *   ok.set(k, false);            // any order; in row order each call is O(1)
 *   if (ok[k]) ...               // O(log intervals)
 */

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace mrpt_fog
{
class IntervalMask
{
   public:
	/** n rows, all set to `value`. */
	void assign(std::size_t n, bool value)
	{
		n_ = n;
		iv_.clear();
		iv_.shrink_to_fit();
		bits_.clear();
		bits_.shrink_to_fit();
		use_bits_ = false;
		if (value && n > 0) iv_.push_back({0, n});
	}
	std::size_t size() const { return n_; }

	bool operator[](std::size_t k) const
	{
		if (use_bits_) return bits_[k];
		// the first interval ending after k
		const auto it = std::upper_bound(iv_.begin(), iv_.end(), k,
										 [](std::size_t v, const Interval& i) { return v < i.second; });
		return it != iv_.end() && it->first <= k;
	}

	void set(std::size_t k, bool value)
	{
		if (use_bits_)
		{
			bits_[k] = value;
			return;
		}
		if ((*this)[k] == value) return;
		auto it = std::upper_bound(iv_.begin(), iv_.end(), k,
								   [](std::size_t v, const Interval& i) { return v < i.second; });
		if (!value)
		{
			// k is inside *it: cut it out
			if (it->first == k && it->second == k + 1) iv_.erase(it);
			else if (it->first == k) it->first++;
			else if (it->second == k + 1) it->second--;
			else
			{
				const Interval right{k + 1, it->second};
				it->second = k;
				iv_.insert(it + 1, right);
			}
		}
		else
		{
			// k is outside every interval: *it (if any) starts after k, it - 1 (if any) ends at or before k
			const bool joins_left = it != iv_.begin() && (it - 1)->second == k;
			const bool joins_right = it != iv_.end() && it->first == k + 1;
			if (joins_left && joins_right)
			{
				(it - 1)->second = it->second;
				iv_.erase(it);
			}
			else if (joins_left) (it - 1)->second = k + 1;
			else if (joins_right) it->first = k;
			else iv_.insert(it, Interval{k, k + 1});
		}
		// more than one bit per row in intervals: a bit vector
		if (iv_.size() * sizeof(Interval) * 8 > n_ + 1024) toBits();
	}

	/** Rows set (O(intervals)). */
	std::size_t count() const
	{
		std::size_t c = 0;
		if (use_bits_)
			for (std::size_t k = 0; k < n_; k++) c += bits_[k];
		else
			for (const auto& i : iv_) c += i.second - i.first;
		return c;
	}
	/** Heap bytes held (for tests of the bound). */
	std::size_t bytes() const { return iv_.capacity() * sizeof(Interval) + bits_.capacity() / 8; }
	bool usesBits() const { return use_bits_; }

   private:
	using Interval = std::pair<std::size_t, std::size_t>;
	void toBits()
	{
		bits_.assign(n_, false);
		for (const auto& i : iv_)
			for (std::size_t k = i.first; k < i.second; k++) bits_[k] = true;
		iv_.clear();
		iv_.shrink_to_fit();
		use_bits_ = true;
	}
	std::size_t n_ = 0;
	std::vector<Interval> iv_;
	std::vector<bool> bits_;
	bool use_bits_ = false;
};

}  // namespace mrpt_fog
