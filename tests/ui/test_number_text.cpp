// What the configuration panel accepts as a number, and how it shows one.

#include <gtest/gtest.h>

#include <QApplication>

#include "legofeup/ui/panels/log_slider.hpp"
#include "legofeup/ui/panels/number_text.hpp"

namespace legofeup::ui {
namespace {

TEST(NumberText, ReadsWhatStudentsTypeExactly) {
    EXPECT_EQ(parse_number(QStringLiteral("1e-9")), 1e-9);
    EXPECT_EQ(parse_number(QStringLiteral(" 1e3 ")), 1000.0);
    EXPECT_EQ(parse_number(QStringLiteral("+0.5")), 0.5);
    EXPECT_EQ(parse_number(QStringLiteral("-3.25")), -3.25);
    EXPECT_EQ(parse_number(QStringLiteral("0.0001")), 1e-4);
}

TEST(NumberText, RefusesAnythingElseRatherThanGuessing) {
    for (const char* text :
         {"", " ", "abc", "1e-9x", "0,5", "1 000", "nan", "inf", "-inf", "1e400", "--1", "0x10"}) {
        EXPECT_FALSE(parse_number(QString::fromLatin1(text)).has_value()) << text;
    }
}

TEST(NumberText, ShowsTheShortestTextThatReadsBackToTheSameValue) {
    for (const double value : {1e-7, 0.12, 3.0, 1.0 / 3.0, 2.5e-12, 1e9}) {
        const QString text = number_text(value);
        EXPECT_EQ(parse_number(text), value) << text.toStdString();
        EXPECT_LE(text.size(), 20);
    }
    EXPECT_EQ(number_text(1e-7), QStringLiteral("1e-07"));
    EXPECT_EQ(number_text(0.001), QStringLiteral("0.001"));
}

TEST(LogSlider, ProposesTwoSignificantDigitsAcrossTheDecades) {
    int argc = 0;
    QApplication app(argc, nullptr);
    LogSlider slider(-14, 4);
    EXPECT_EQ(slider.valueAt(-9 * 20), 1e-9);
    EXPECT_EQ(slider.valueAt(3 * 20), 1e3);
    EXPECT_EQ(slider.valueAt(-4 * 20 + 10), 3.2e-4);  // 10^-3.5 = 3.16e-4
    slider.showValue(1e-4);
    EXPECT_EQ(slider.value(), -80);
    slider.showValue(1e-30);  // beyond the span: at the end, the value itself untouched
    EXPECT_EQ(slider.value(), slider.minimum());
    double proposed = 0.0;
    QObject::connect(&slider, &LogSlider::valueProposed, [&](double value) { proposed = value; });
    slider.setValue(-20);
    EXPECT_EQ(proposed, 0.1);
}

}  // namespace
}  // namespace legofeup::ui
