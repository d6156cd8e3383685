// legofeup-cli report as a student runs it: chosen steps run, the submission's names,
// answers and tuning in the report, bad input refused with where it is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::read_file;
using legofeup::testing::Result;

class ReportCli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }
};

TEST_F(ReportCli, ReportsTheChosenStepsWithTheSubmissionsAnswersAndTuning) {
    const fs::path submission = write("submission.toml", R"(lesson = "legofeup"
students = "Ana Silva & Rui Costa"

[answers.a]
q1 = """The ellipse <b>keeps</b> growing: nothing corrects it."""

[answers.f]
q2 = "Yes, the NEES stays inside its bounds."

[tuning.filter]
q11 = 3e-7
)");
    const fs::path out = dir_ / "report";
    const Result result = run("report --lesson legofeup --submission " + submission.string()
                              + " --steps a,f --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    // One line per step run, with its checks.
    EXPECT_NE(result.out.find("step a  Odometry only: 2 of 2 checks passed"), std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("step f  Tuned filter: "), std::string::npos) << result.out;
    EXPECT_EQ(result.out.find("step b"), std::string::npos) << result.out;

    const std::string html = read_file(out / "report.html");
    EXPECT_NE(html.find("Ana Silva &amp; Rui Costa"), std::string::npos);
    EXPECT_NE(html.find("The ellipse &lt;b&gt;keeps&lt;/b&gt; growing"), std::string::npos);
    EXPECT_NE(html.find("Yes, the NEES stays inside its bounds."), std::string::npos);
    // Steps b–e, g and h were not run; step f ran with the submission's Q11, not the preset's
    // 1e-6.
    std::size_t not_run = 0;
    for (auto at = html.find("This step was not run."); at != std::string::npos;
         at = html.find("This step was not run.", at + 1)) {
        ++not_run;
    }
    EXPECT_EQ(not_run, 6U);
    const auto f = html.find("id=\"step-f\"");
    ASSERT_NE(f, std::string::npos);
    const auto q11 = html.find("<code>filter.q11</code>", f);
    ASSERT_NE(q11, std::string::npos);
    EXPECT_NE(html.substr(q11, 80).find(">3e-0"), std::string::npos) << html.substr(q11, 80);
    EXPECT_EQ(read_file(out / "report.pdf").rfind("%PDF-", 0), 0U);
}

TEST_F(ReportCli, AMalformedSubmissionIsRefusedWithItsLine) {
    const fs::path submission = write("bad.toml",
                                      "lesson = \"legofeup\"\n"
                                      "students = \"Ana\"\n"
                                      "[answers.z]\n"
                                      "q1 = \"no such step\"\n");
    const fs::path out = dir_ / "report";
    const Result result =
        run("report --submission " + submission.string() + " --steps a --out " + out.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("bad.toml:3"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out / "report.html"));
    EXPECT_FALSE(fs::exists(out / "report.pdf"));
}

TEST_F(ReportCli, AnUnknownStepIsRefused) {
    const Result result = run("report --steps a,x --out " + (dir_ / "report").string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("--steps"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("a, b, c, d, e, f"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(dir_ / "report"));
}

}  // namespace
