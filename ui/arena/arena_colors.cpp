#include "legofeup/ui/arena/arena_colors.hpp"

#include <algorithm>
#include <cmath>

#include "arena_drawing.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::with_alpha;

double linear_channel(int value) {
    const double c = value / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double relative_luminance(const QColor& color) {
    const QColor rgb = color.toRgb();
    return 0.2126 * linear_channel(rgb.red()) + 0.7152 * linear_channel(rgb.green())
           + 0.0722 * linear_channel(rgb.blue());
}

}  // namespace

QColor mix(const QColor& a, const QColor& b, double t) {
    const auto channel = [t](int x, int y) {
        return static_cast<int>(std::lround(x * t + y * (1.0 - t)));
    };
    return {channel(a.red(), b.red()), channel(a.green(), b.green()), channel(a.blue(), b.blue())};
}

double contrast_ratio(const QColor& a, const QColor& b) {
    const double la = relative_luminance(a);
    const double lb = relative_luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

ArenaColors arena_colors(const QPalette& palette) {
    ArenaColors colors;
    colors.background = palette.color(QPalette::Active, QPalette::Base);
    // Text and WindowText are normally the same; take whichever reads better on Base.
    const QColor text = palette.color(QPalette::Active, QPalette::Text);
    const QColor window_text = palette.color(QPalette::Active, QPalette::WindowText);
    colors.foreground =
        contrast_ratio(text, colors.background) >= contrast_ratio(window_text, colors.background)
            ? text
            : window_text;
    colors.dark = relative_luminance(colors.background) < 0.18;
    const bool dark = colors.dark;
    // Material palette shades: 800 on light backgrounds, 300 on dark ones (all ≥ 4.5:1
    // against white or against #202020 respectively).
    colors.truth = dark ? QColor(0x81, 0xc7, 0x84) : QColor(0x2e, 0x7d, 0x32);       // green
    colors.estimate = dark ? QColor(0x64, 0xb5, 0xf6) : QColor(0x15, 0x65, 0xc0);    // blue
    colors.odometry = dark ? QColor(0xff, 0xb7, 0x4d) : QColor(0xbf, 0x36, 0x0c);    // orange
    colors.ellipse = dark ? QColor(0xf0, 0x62, 0x92) : QColor(0xad, 0x14, 0x57);     // pink
    colors.associated = dark ? QColor(0x4d, 0xd0, 0xe1) : QColor(0x00, 0x83, 0x8f);  // cyan
    colors.rejected = dark ? QColor(0xef, 0x53, 0x50) : QColor(0xc6, 0x28, 0x28);    // red
    colors.beacon = dark ? QColor(0xff, 0xd5, 0x4f) : QColor(0x6d, 0x4c, 0x41);  // amber / brown
    colors.shadow = dark ? QColor(0xce, 0x93, 0xd8) : QColor(0x6a, 0x1b, 0x9a);  // purple
    colors.out_of_range = with_alpha(colors.foreground, 130);
    // Blue grey: quieter than the estimate's blue and the truth's green it surrounds.
    colors.particles = dark ? QColor(0xb0, 0xbe, 0xc5) : QColor(0x37, 0x47, 0x4f);
    // The map: walls nearly as strong as the arena's walls, unknown space a light grey (both
    // opaque mixes, drawn once per run into the map's picture).
    colors.map_occupied = mix(colors.foreground, colors.background, 0.78);
    colors.map_unknown = mix(colors.foreground, colors.background, 0.16);
    colors.filter_map = with_alpha(colors.shadow, 150);
    colors.expected_scan = mix(colors.foreground, colors.background, 0.62);
    colors.truth_scan = mix(colors.truth, colors.background, 0.6);
    colors.trail = mix(colors.ellipse, colors.background, dark ? 0.45 : 0.38);
    colors.grid = mix(colors.foreground, colors.background, dark ? 0.11 : 0.09);
    colors.path = mix(colors.foreground, colors.background, 0.47);
    colors.label_background = with_alpha(colors.background, 215);
    return colors;
}

}  // namespace legofeup::ui
