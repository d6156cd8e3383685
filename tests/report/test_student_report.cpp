// The student report of a small hand-built lesson: one step run (one lap), one not run. The
// HTML must carry every step, the escaped answers, the checks' outcomes and inline plots; the
// PDF must exist with a sensible number of pages; a failed write must leave no file.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/report/student_report.hpp"
#include "report_content.hpp"
#include "report_pdf.hpp"

namespace legofeup::report {
namespace {

namespace fs = std::filesystem;
using lessons::MetricCheck;

MetricCheck check(const std::string& metric, MetricCheck::Op op, double threshold,
                  const std::string& expression) {
    MetricCheck c;
    c.metric = metric;
    c.op = op;
    c.threshold = threshold;
    c.expression = expression;
    c.description = "what " + metric + " says";
    return c;
}

lessons::Lesson make_lesson() {
    lessons::Lesson lesson;
    lesson.id = "test";
    lesson.title = "A test lesson";
    lesson.goals = "Learn **why** odometry drifts.";
    lessons::LessonStep a;
    a.id = "a";
    a.title = "Odometry & drift";
    a.instructions = "Drive *one* lap.";
    a.expectation = "The estimate DRIFTS-CONCLUSION away.";
    a.questions = {{"q1", "Why does it drift?"}, {"q2", "How far?"}};
    // The first check passes on any run, the second fails on any run.
    a.checks = {
        check("final_position_error_m", MetricCheck::Op::Greater, 0.0,
              "final_position_error_m > 0"),
        check("rms_position_error_m", MetricCheck::Op::Less, 0.0, "rms_position_error_m < 0")};
    a.config.laps = 1;
    lessons::LessonStep b;
    b.id = "b";
    b.title = "The step nobody ran";
    b.instructions = "Not today.";
    b.expectation = "HIDDEN-CONCLUSION of b.";
    b.questions = {{"q1", "Anything?"}};
    lesson.steps = {a, b};
    return lesson;
}

// The run is the slow part: done once for all tests.
const StudentReport& sample_report() {
    static const StudentReport report = [] {
        StudentReport r;
        r.lesson = make_lesson();
        r.students = "Ana <Silva> & Rui";
        r.created = "2024-05-01 10:00";
        StepOutcome a = run_step(r.lesson.steps[0], r.lesson.steps[0].config);
        a.answers["q1"] = "Because <script>alert(1)</script> the *wheels* differ.";
        StepOutcome b;
        b.step_id = "b";
        r.steps = {a, b};
        return r;
    }();
    return report;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path fresh_directory(const std::string& name) {
    const fs::path dir = fs::path(LEGOFEUP_TEST_TMP) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Counts pages drawn, on a recording surface (nothing is rasterised).
class CountingSink final : public pages::PageSink {
  public:
    CountingSink()
        : surface_(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr)),
          cr_(cairo_create(surface_)) {}
    ~CountingSink() override {
        cairo_destroy(cr_);
        cairo_surface_destroy(surface_);
    }
    cairo_t* begin_page() override {
        ++begun;
        return cr_;
    }
    void end_page() override {
        ++ended;
        EXPECT_EQ(cairo_status(cr_), CAIRO_STATUS_SUCCESS);
    }
    int begun = 0;
    int ended = 0;

  private:
    cairo_surface_t* surface_;
    cairo_t* cr_;
};

TEST(StudentReport, RunStepFillsMetricsChecksRecordingAndWorld) {
    const StepOutcome& a = sample_report().steps[0];
    EXPECT_TRUE(a.ran);
    EXPECT_EQ(a.step_id, "a");
    EXPECT_EQ(a.config.laps, 1);
    ASSERT_TRUE(a.metrics.contains("final_position_error_m"));
    EXPECT_GT(a.metrics["final_position_error_m"].get<double>(), 0.0);
    ASSERT_EQ(a.checks.size(), 2U);
    EXPECT_TRUE(a.checks[0].passed);
    EXPECT_FALSE(a.checks[1].passed);
    EXPECT_DOUBLE_EQ(a.checks[1].actual, a.metrics["rms_position_error_m"].get<double>());
    EXPECT_GT(a.recording.steps().size(), 100U);
    EXPECT_FALSE(a.world.walls.empty());
}

TEST(StudentReport, AMetricWithoutTruthReadsAsAbsentNotZero) {
    // The same counts, once without the truth and once with it (measured as 0.012 m).
    lessons::RunResult result;
    result.metrics.steps = 400;
    result.metrics.updates_applied = 120;
    const auto rows_of = [](const lessons::RunResult& run) {
        std::map<std::string, std::string> rows;
        for (const content::MetricRow& row :
             content::metric_rows(lessons::result_metrics_to_json(run))) {
            rows[row.name] = row.value;
        }
        return rows;
    };
    auto blind = rows_of(result);
    EXPECT_EQ(blind["final_position_error_m"], "— (no ground truth on this link)");
    EXPECT_EQ(blind["mean_nees"], "— (no ground truth on this link)");
    EXPECT_EQ(blind["updates_applied"], "120");
    EXPECT_EQ(blind["steps"], "400");
    result.metrics.truth = TruthMetrics{};
    result.metrics.truth->final_position_error = 0.012;
    auto seen = rows_of(result);
    EXPECT_EQ(seen["final_position_error_m"], "0.012");
    EXPECT_EQ(seen["mean_nees"], "0");  // measured as 0: shown as 0
    EXPECT_EQ(seen["updates_applied"], "120");
}

TEST(StudentReport, HtmlHasEveryStepEscapedAnswersCheckOutcomesAndInlinePlots) {
    const std::string html = report_html(sample_report());
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0U);
    EXPECT_EQ(html, report_html(sample_report()));  // the same report, the same text
    EXPECT_NE(html.find("Step a — Odometry &amp; drift"), std::string::npos);
    EXPECT_NE(html.find("Step b — The step nobody ran"), std::string::npos);
    EXPECT_NE(html.find("Ana &lt;Silva&gt; &amp; Rui"), std::string::npos);
    // The answer is shown, its markup escaped and its Markdown rendered.
    EXPECT_NE(html.find("Because &lt;script&gt;alert(1)&lt;/script&gt; the <em>wheels</em>"),
              std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(count(html, "Not answered."), 2U);  // a's q2 and b's q1
    EXPECT_EQ(count(html, "✔ passed"), 1U);
    EXPECT_EQ(count(html, "✘ failed"), 1U);
    EXPECT_NE(html.find("1 of 2 checks passed"), std::string::npos);
    EXPECT_NE(html.find("This step was not run."), std::string::npos);
    // The conclusion of a step is shown only once it has run.
    EXPECT_NE(html.find("DRIFTS-CONCLUSION"), std::string::npos);
    EXPECT_EQ(html.find("HIDDEN-CONCLUSION"), std::string::npos);
    // Five plots of the one run, inline, their cairo ids made unique per figure.
    EXPECT_EQ(count(html, "<svg"), 5U);
    EXPECT_EQ(count(html, "id=\"glyph"), 0U);
    EXPECT_GT(count(html, "id=\"sa-trajectory-glyph"), 0U);
    // Self-contained: nothing fetched, nothing run.
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(html.find("src="), std::string::npos);
    // The parameters always include the seed, Q, R and P0, and what differs (laps).
    for (const char* key :
         {"<code>seed</code>", "<code>filter.q11</code>", "<code>filter.r22</code>",
          "<code>initial.var_theta</code>", "<code>laps</code>"}) {
        EXPECT_NE(html.find(key), std::string::npos) << key;
    }
    EXPECT_EQ(html.find("<code>control.routine</code>"), std::string::npos);
}

TEST(StudentReport, PdfIsWrittenWithPagesForEveryPart) {
    const fs::path dir = fresh_directory("pdf");
    write_report(sample_report(), dir);
    const std::string pdf = read(dir / "report.pdf");
    ASSERT_GT(pdf.size(), 1000U);
    EXPECT_EQ(pdf.rfind("%PDF-", 0), 0U);
    EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
    const std::regex page(R"(/Type\s*/Page[^s])");
    const auto pages = static_cast<int>(
        std::distance(std::sregex_iterator(pdf.begin(), pdf.end(), page), std::sregex_iterator()));
    CountingSink sink;
    const int drawn = draw_report_pages(sample_report(), sink);
    EXPECT_EQ(pages, drawn);
    EXPECT_EQ(sink.begun, drawn);
    EXPECT_EQ(sink.ended, drawn);
    // A front page, the run step over a few pages (five plots), the step not run.
    EXPECT_GE(pages, 4);
    EXPECT_LE(pages, 12);
    EXPECT_EQ(read(dir / "report.html"), report_html(sample_report()));
    for (const auto& entry : fs::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
    }
}

TEST(StudentReport, LongAnswersBreakAcrossPages) {
    StudentReport report = sample_report();
    CountingSink short_sink;
    const int short_pages = draw_report_pages(report, short_sink);
    std::string long_answer;
    for (int i = 0; i < 300; ++i) {
        long_answer += "Line " + std::to_string(i) + " of a very long answer.\n\n";
    }
    report.steps[1].answers["q1"] = long_answer;
    CountingSink long_sink;
    const int long_pages = draw_report_pages(report, long_sink);
    // 300 paragraphs of one line (about 18 points each) need about 6–9 more pages.
    EXPECT_GE(long_pages, short_pages + 5);
    EXPECT_LE(long_pages, short_pages + 12);
}

TEST(StudentReport, FailedWriteThrowsAndLeavesNoFile) {
    const fs::path dir = fresh_directory("atomic");
    // The PDF's temporary name is taken by a directory: the PDF cannot be written.
    fs::create_directories(dir / "report.pdf.partial" / "occupied");
    EXPECT_THROW(write_report(sample_report(), dir), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "report.html"));
    EXPECT_FALSE(fs::exists(dir / "report.html.partial"));
    EXPECT_FALSE(fs::exists(dir / "report.pdf"));
}

TEST(StudentReport, NeitherFileIsReplacedBeforeBothAreComplete) {
    const fs::path dir = fresh_directory("atomic_rename");
    // report.html's name is taken by a directory that is not empty: its rename fails, after
    // both files were written, and the PDF is not renamed either.
    fs::create_directories(dir / "report.html" / "occupied");
    try {
        write_report(sample_report(), dir);
        FAIL() << "no error";
    } catch (const fileio::WriteError& error) {
        EXPECT_EQ(error.path(), dir / "report.html");
        EXPECT_EQ(error.step(), "renaming " + (dir / "report.html.partial").string() + " over it");
    }
    EXPECT_TRUE(fs::is_directory(dir / "report.html" / "occupied"));
    EXPECT_FALSE(fs::exists(dir / "report.pdf"));
    EXPECT_FALSE(fs::exists(dir / "report.html.partial"));
    EXPECT_FALSE(fs::exists(dir / "report.pdf.partial"));
}

TEST(StudentReport, UncreatableDirectoryThrowsNamingIt) {
    const fs::path dir = fresh_directory("not_a_directory");
    std::ofstream(dir / "file") << "x";
    try {
        write_report(sample_report(), dir / "file" / "report");
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("file/report"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace legofeup::report
