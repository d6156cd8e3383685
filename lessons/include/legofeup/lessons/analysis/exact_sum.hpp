#pragma once
// A sum of doubles whose result does not depend on the order of the additions. Floating-point
// addition is not associative, so summing run 0, 1, 2, 3 in one process and (0, 2) + (1, 3)
// in two shards would differ in the last bits. Here every value is rounded once to a
// multiple of 2⁻⁶⁰ (about 8.7·10⁻¹⁹) and added as a 128-bit integer: integer addition is
// exact and associative, so any split into shards, merged in any order, gives the same bits.

#include <optional>
#include <string>
#include <string_view>

namespace legofeup::lessons::analysis {

class ExactSum {
  public:
    /// Values are kept in units of 2^-kFractionBits.
    static constexpr int kFractionBits = 60;
    /// Larger magnitudes are clamped to this (a NEES of 10¹⁵ is as wrong as any larger one);
    /// 10⁵ of them still fit the 128-bit sum.
    static constexpr double kLimit = 1e15;

    /// Adds `value` (finite; NaN counts as 0) rounded to the nearest unit.
    void add(double value);
    ExactSum& operator+=(const ExactSum& other);
    /// The sum, rounded once to the nearest double.
    double value() const;

    /// The sum as text for shard files ("-" for negative, then hexadecimal units), and back.
    std::string to_text() const;
    static std::optional<ExactSum> from_text(std::string_view text);

    bool operator==(const ExactSum& other) const { return units_ == other.units_; }

  private:
    __extension__ typedef __int128 Units;
    Units units_ = 0;
};

}  // namespace legofeup::lessons::analysis
