// The student report as one HTML document: plain CSS for screen and print, plots inline as
// SVG, no scripts and nothing fetched from elsewhere.

#include <string_view>

#include "legofeup/report/student_report.hpp"
#include "markdown.hpp"
#include "report_content.hpp"

namespace legofeup::report {
namespace {

using markdown::escape;

constexpr std::string_view kStyle = R"(
body { font-family: "DejaVu Sans", "Helvetica Neue", Arial, sans-serif; color: #1a1a1a;
       max-width: 60em; margin: 2em auto; padding: 0 1.5em; line-height: 1.45; }
header { border-bottom: 2px solid #1f66cc; margin-bottom: 1.5em; }
h1 { margin-bottom: 0.2em; }
h2 { color: #1f66cc; border-bottom: 1px solid #ccd; padding-bottom: 0.15em; margin-top: 2em; }
h3 { margin-top: 1.4em; }
.meta { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccd; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #eef2f8; }
td.number { font-family: "DejaVu Sans Mono", monospace; white-space: nowrap; }
.passed { color: #1a7f37; font-weight: bold; white-space: nowrap; }
.failed { color: #c62828; font-weight: bold; white-space: nowrap; }
.not-run { color: #8a5a00; font-style: italic; }
figure { margin: 1em 0; break-inside: avoid; page-break-inside: avoid; }
svg.plot { width: 100%; height: auto; display: block; border: 1px solid #eee; }
.question { margin: 1em 0 0.3em 0; font-weight: bold; }
.answer { border-left: 4px solid #1f66cc; background: #f5f8fc; margin: 0.3em 0 1em 0;
          padding: 0.2em 1em; }
.unanswered { color: #c62828; font-style: italic; }
.expectation { border-left: 4px solid #1a7f37; background: #f3faf5; padding: 0.2em 1em; }
code, pre { font-family: "DejaVu Sans Mono", monospace; background: #f4f4f4; }
pre { padding: 0.5em; overflow-x: auto; }
@page { size: A4; margin: 16mm; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 10.5pt; }
  section.step { break-before: page; page-break-before: always; }
  h2, h3 { break-after: avoid; page-break-after: avoid; }
  tr { break-inside: avoid; page-break-inside: avoid; }
}
)";

void replace_all(std::string& text, std::string_view from, const std::string& to) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
}

// Cairo numbers the group of each SVG surface it ever made ("surface6"); nothing refers to
// it, and dropping it makes the same report the same text every time.
void drop_surface_ids(std::string& svg) {
    constexpr std::string_view kId = " id=\"surface";
    if (svg.find("#surface") != std::string::npos) {
        return;
    }
    for (auto at = svg.find(kId); at != std::string::npos; at = svg.find(kId, at)) {
        svg.erase(at, svg.find('"', at + kId.size()) + 1 - at);
    }
}

// A figure as an inline <svg>. Cairo names its glyphs and clips the same way in every SVG
// ("glyph0-1", "clip1"); in one page the first of each name would win, so every id and
// reference gets the figure's own prefix.
std::string inline_svg(const plot::Figure& figure, const std::string& prefix) {
    std::string svg = figure.svg();
    svg.erase(0, svg.find("<svg"));
    drop_surface_ids(svg);
    replace_all(svg, "id=\"", "id=\"" + prefix);
    replace_all(svg, "href=\"#", "href=\"#" + prefix);
    replace_all(svg, "url(#", "url(#" + prefix);
    svg.insert(4, " class=\"plot\" role=\"img\" aria-label=\"" + escape(figure.title()) + "\"");
    return svg;
}

void parameters(std::string& html, const StepOutcome& outcome) {
    html +=
        "<h3>Parameters</h3>\n<p>The seed, Q, R and P0, and every setting that differs from "
        "the defaults.</p>\n<table>\n<tr><th>Setting</th><th>Value</th><th>Default</th>"
        "<th>Meaning</th></tr>\n";
    for (const content::ParameterRow& row : content::parameter_rows(outcome.config)) {
        html += "<tr><td><code>" + escape(row.key) + "</code></td><td class=\"number\">"
                + escape(row.value) + "</td><td class=\"number\">" + escape(row.default_value)
                + "</td><td>" + escape(row.meaning) + "</td></tr>\n";
    }
    html += "</table>\n";
}

void plots(std::string& html, const StepOutcome& outcome, const std::string& step_title) {
    html += "<h3>Plots</h3>\n";
    for (const RunFigure& figure : run_figures(outcome.recording.thinned(kReportPlotSteps),
                                               outcome.world, step_title, content::kFigureWidth)) {
        html += "<figure>\n"
                + inline_svg(figure.figure, "s" + outcome.step_id + "-" + figure.name + "-")
                + "\n</figure>\n";
    }
}

void metrics(std::string& html, const StepOutcome& outcome) {
    html += "<h3>Metrics</h3>\n<table>\n<tr><th>Metric</th><th>Value</th></tr>\n";
    for (const content::MetricRow& row : content::metric_rows(outcome.metrics)) {
        html += "<tr><td><code>" + escape(row.name) + "</code></td><td class=\"number\">"
                + escape(row.value) + "</td></tr>\n";
    }
    html += "</table>\n";
}

void checks(std::string& html, const StepOutcome& outcome) {
    html += "<h3>Automatic checks</h3>\n";
    if (outcome.checks.empty()) {
        html += "<p>This step has no automatic checks.</p>\n";
        return;
    }
    html += "<p>" + content::checks_summary(outcome.checks) + ".</p>\n<table>\n<tr><th>Result</th>"
            "<th>Check</th><th>What it means</th><th>Measured</th></tr>\n";
    for (const lessons::CheckResult& check : outcome.checks) {
        html += std::string("<tr><td class=\"") + (check.passed ? "passed" : "failed") + "\">"
                + content::check_mark(check.passed) + "</td><td><code>"
                + escape(check.check.expression) + "</code></td><td>"
                + escape(check.check.description) + "</td><td>" + escape(check.message)
                + "</td></tr>\n";
    }
    html += "</table>\n";
}

void questions(std::string& html, const lessons::LessonStep& step, const StepOutcome* outcome) {
    if (step.questions.empty()) {
        return;
    }
    html += "<h3>Questions</h3>\n";
    for (std::size_t i = 0; i < step.questions.size(); ++i) {
        const lessons::LessonQuestion& question = step.questions[i];
        html += "<div class=\"question\">Question " + std::to_string(i + 1) + "</div>\n"
                + markdown_to_html(question.text);
        if (const std::string* answer = content::find_answer(outcome, question.id)) {
            html += "<div class=\"answer\">\n" + markdown_to_html(*answer) + "</div>\n";
        } else {
            html += "<p class=\"unanswered\">Not answered.</p>\n";
        }
    }
}

void step_section(std::string& html, const lessons::LessonStep& step, const StepOutcome* outcome) {
    const std::string title = "Step " + step.id + " — " + step.title;
    html += "<section class=\"step\" id=\"step-" + escape(step.id) + "\">\n<h2>" + escape(title)
            + "</h2>\n<h3>Instructions</h3>\n" + markdown_to_html(step.instructions);
    if (outcome != nullptr && outcome->ran) {
        parameters(html, *outcome);
        plots(html, *outcome, title);
        metrics(html, *outcome);
        checks(html, *outcome);
        html += "<h3>Expected conclusion</h3>\n<div class=\"expectation\">\n"
                + markdown_to_html(step.expectation) + "</div>\n";
    } else {
        html += "<p class=\"not-run\">This step was not run.</p>\n";
    }
    questions(html, step, outcome);
    html += "</section>\n";
}

void overview(std::string& html, const StudentReport& report) {
    html += "<h2>Steps</h2>\n<table>\n<tr><th>Step</th><th>Title</th><th>Checks</th></tr>\n";
    for (const lessons::LessonStep& step : report.lesson.steps) {
        const StepOutcome* outcome = content::find_outcome(report, step.id);
        const bool ran = outcome != nullptr && outcome->ran;
        html += "<tr><td><a href=\"#step-" + escape(step.id) + "\">" + escape(step.id)
                + "</a></td><td>" + escape(step.title) + "</td><td>"
                + (ran ? escape(content::checks_summary(outcome->checks))
                       : std::string("<span class=\"not-run\">not run</span>"))
                + "</td></tr>\n";
    }
    html += "</table>\n";
}

}  // namespace

std::string report_html(const StudentReport& report) {
    std::string html =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<title>"
        + escape(report.lesson.title) + " — report</title>\n<style>" + std::string(kStyle)
        + "</style>\n</head>\n<body>\n<header>\n<h1>" + escape(report.lesson.title)
        + "</h1>\n<p class=\"meta\">Students: "
        + (report.students.empty() ? "(not given)" : escape(report.students))
        + "<br>Date: " + escape(report.created) + "</p>\n</header>\n";
    html += "<h2>Goals</h2>\n" + markdown_to_html(report.lesson.goals);
    overview(html, report);
    for (const lessons::LessonStep& step : report.lesson.steps) {
        step_section(html, step, content::find_outcome(report, step.id));
    }
    html += "</body>\n</html>\n";
    return html;
}

}  // namespace legofeup::report
