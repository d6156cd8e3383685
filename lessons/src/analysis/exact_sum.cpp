#include "legofeup/lessons/analysis/exact_sum.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup::lessons::analysis {

void ExactSum::add(double value) {
    if (std::isnan(value)) {
        return;
    }
    const double clamped = std::clamp(value, -kLimit, kLimit);
    // |clamped| · 2⁶⁰ < 2⁵⁰ · 2⁶⁰ = 2¹¹⁰: the conversion to 128 bits cannot overflow.
    units_ += static_cast<Units>(std::nearbyint(std::ldexp(clamped, kFractionBits)));
}

ExactSum& ExactSum::operator+=(const ExactSum& other) {
    units_ += other.units_;
    return *this;
}

double ExactSum::value() const {
    return std::ldexp(static_cast<double>(units_), -kFractionBits);
}

std::string ExactSum::to_text() const {
    constexpr char kDigits[] = "0123456789abcdef";
    Units magnitude = units_ < 0 ? -units_ : units_;
    std::string digits;
    do {
        digits.push_back(kDigits[static_cast<int>(magnitude % 16)]);
        magnitude /= 16;
    } while (magnitude != 0);
    if (units_ < 0) {
        digits.push_back('-');
    }
    std::reverse(digits.begin(), digits.end());
    return digits;
}

std::optional<ExactSum> ExactSum::from_text(std::string_view text) {
    const bool negative = !text.empty() && text.front() == '-';
    if (negative) {
        text.remove_prefix(1);
    }
    if (text.empty()) {
        return std::nullopt;
    }
    constexpr Units kLargest = ~(Units(1) << 127);
    Units magnitude = 0;
    for (const char c : text) {
        int digit = 0;
        if (c >= '0' && c <= '9') {
            digit = c - '0';
        } else if (c >= 'a' && c <= 'f') {
            digit = c - 'a' + 10;
        } else {
            return std::nullopt;
        }
        if (magnitude > (kLargest - digit) / 16) {
            return std::nullopt;  // more than 127 bits
        }
        magnitude = magnitude * 16 + digit;
    }
    ExactSum sum;
    sum.units_ = negative ? -magnitude : magnitude;
    return sum;
}

}  // namespace legofeup::lessons::analysis
