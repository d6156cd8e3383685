#include "report_pdf.hpp"

#include <cairo-pdf.h>

#include <memory>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "cairo_stream.hpp"
#include "markdown.hpp"
#include "report_content.hpp"

namespace legofeup::report {
namespace {

using markdown::escape;
using pages::PageLayout;

std::string code(const std::string& text) {
    return "<tt>" + escape(text) + "</tt>";
}

std::string colored(const std::string& markup, const char* color) {
    return std::string("<span foreground=\"") + color + "\">" + markup + "</span>";
}

pages::TextStyle answer_style() {
    pages::TextStyle style;
    style.bar = "#1f66cc";
    style.background = "#f5f8fc";
    return style;
}

void parameters(PageLayout& layout, const StepOutcome& outcome) {
    layout.heading("Parameters", 3);
    layout.paragraph("The seed, Q, R and P0, and every setting that differs from the defaults.");
    std::vector<std::vector<std::string>> rows;
    for (const content::ParameterRow& row : content::parameter_rows(outcome.config)) {
        rows.push_back(
            {code(row.key), code(row.value), code(row.default_value), escape(row.meaning)});
    }
    layout.table({{"Setting", 0.24}, {"Value", 0.16}, {"Default", 0.16}, {"Meaning", 0.44}}, rows);
}

void plots(PageLayout& layout, const StepOutcome& outcome, const std::string& step_title) {
    const std::vector<RunFigure> figures =
        run_figures(outcome.recording.thinned(kReportPlotSteps), outcome.world, step_title,
                    content::kFigureWidth);
    layout.heading("Plots", 3, layout.smallest_figure_height(figures.front().figure));
    for (const RunFigure& figure : figures) {
        layout.figure(figure.figure);
    }
}

void metrics(PageLayout& layout, const StepOutcome& outcome) {
    layout.heading("Metrics", 3);
    std::vector<std::vector<std::string>> rows;
    for (const content::MetricRow& row : content::metric_rows(outcome.metrics)) {
        rows.push_back({code(row.name), escape(row.value)});
    }
    layout.table({{"Metric", 0.45}, {"Value", 0.55}}, rows);
}

void checks(PageLayout& layout, const StepOutcome& outcome) {
    layout.heading("Automatic checks", 3);
    if (outcome.checks.empty()) {
        layout.paragraph("This step has no automatic checks.");
        return;
    }
    layout.paragraph(escape(content::checks_summary(outcome.checks)) + ".");
    std::vector<std::vector<std::string>> rows;
    for (const lessons::CheckResult& check : outcome.checks) {
        rows.push_back({colored("<b>" + std::string(content::check_mark(check.passed)) + "</b>",
                                check.passed ? "#1a7f37" : "#c62828"),
                        code(check.check.expression), escape(check.check.description),
                        escape(check.message)});
    }
    layout.table({{"Result", 0.13}, {"Check", 0.27}, {"What it means", 0.3}, {"Measured", 0.3}},
                 rows);
}

void questions(PageLayout& layout, const lessons::LessonStep& step, const StepOutcome* outcome) {
    if (step.questions.empty()) {
        return;
    }
    layout.heading("Questions", 3);
    pages::TextStyle label;
    label.bold = true;
    label.space_after = 3.0;
    for (std::size_t i = 0; i < step.questions.size(); ++i) {
        const lessons::LessonQuestion& question = step.questions[i];
        layout.paragraph("Question " + std::to_string(i + 1), label);
        layout.markdown(question.text);
        if (const std::string* answer = content::find_answer(outcome, question.id)) {
            layout.markdown(*answer, answer_style());
        } else {
            layout.paragraph(colored("<i>Not answered.</i>", "#c62828"));
        }
        layout.space(4.0);
    }
}

void step_pages(PageLayout& layout, const lessons::LessonStep& step, const StepOutcome* outcome) {
    const std::string title = "Step " + step.id + " — " + step.title;
    layout.page_break();
    layout.heading(title, 2);
    layout.heading("Instructions", 3);
    layout.markdown(step.instructions);
    if (outcome != nullptr && outcome->ran) {
        parameters(layout, *outcome);
        plots(layout, *outcome, title);
        metrics(layout, *outcome);
        checks(layout, *outcome);
        layout.heading("Expected conclusion", 3);
        pages::TextStyle conclusion;
        conclusion.bar = "#1a7f37";
        conclusion.background = "#f3faf5";
        layout.markdown(step.expectation, conclusion);
    } else {
        layout.paragraph(colored("<i>This step was not run.</i>", "#8a5a00"));
    }
    questions(layout, step, outcome);
}

void front_page(PageLayout& layout, const StudentReport& report) {
    layout.heading(report.lesson.title, 1);
    pages::TextStyle meta;
    meta.space_after = 14.0;
    layout.paragraph(colored("Students: "
                                 + (report.students.empty() ? std::string("(not given)")
                                                            : escape(report.students))
                                 + "\nDate: " + escape(report.created),
                             "#555555"),
                     meta);
    layout.heading("Goals", 2);
    layout.markdown(report.lesson.goals);
    layout.heading("Steps", 2);
    std::vector<std::vector<std::string>> rows;
    for (const lessons::LessonStep& step : report.lesson.steps) {
        const StepOutcome* outcome = content::find_outcome(report, step.id);
        const bool ran = outcome != nullptr && outcome->ran;
        rows.push_back({escape(step.id), escape(step.title),
                        ran ? escape(content::checks_summary(outcome->checks))
                            : colored("<i>not run</i>", "#8a5a00")});
    }
    layout.table({{"Step", 0.1}, {"Title", 0.6}, {"Checks", 0.3}}, rows);
}

// A PDF written to a stream (an AtomicFile's): one surface, a page per begin/end.
class PdfSink final : public pages::PageSink {
  public:
    PdfSink(std::ostream& out, std::filesystem::path shown_path)
        : out_(out),
          path_(std::move(shown_path)),
          surface_(cairo_pdf_surface_create_for_stream(write_to_stream, &out_, pages::kPageWidth,
                                                       pages::kPageHeight),
                   cairo_surface_destroy),
          cr_(cairo_create(surface_.get()), cairo_destroy) {
        check();
    }
    cairo_t* begin_page() override { return cr_.get(); }
    void end_page() override { cairo_show_page(cr_.get()); }

    void finish(const std::string& title) {
        cairo_pdf_surface_set_metadata(surface_.get(), CAIRO_PDF_METADATA_TITLE, title.c_str());
        check();
        cr_.reset();
        cairo_surface_finish(surface_.get());
        check();
    }

  private:
    void check() const {
        cairo_status_t status = cairo_surface_status(surface_.get());
        if (status == CAIRO_STATUS_SUCCESS && cr_) {
            status = cairo_status(cr_.get());
        }
        if (status != CAIRO_STATUS_SUCCESS) {
            throw std::runtime_error("cannot write " + path_.string() + ": "
                                     + cairo_status_to_string(status));
        }
    }

    std::ostream& out_;
    std::filesystem::path path_;
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_;
};

}  // namespace

int draw_report_pages(const StudentReport& report, pages::PageSink& sink) {
    PageLayout layout(
        sink, report.lesson.title + (report.students.empty() ? "" : " — " + report.students));
    front_page(layout, report);
    for (const lessons::LessonStep& step : report.lesson.steps) {
        step_pages(layout, step, content::find_outcome(report, step.id));
    }
    return layout.finish();
}

void write_report_pdf(const StudentReport& report, std::ostream& out,
                      const std::filesystem::path& shown_path) {
    PdfSink sink(out, shown_path);
    draw_report_pages(report, sink);
    sink.finish(report.lesson.title);
}

}  // namespace legofeup::report
