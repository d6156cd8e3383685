// Markdown of lessons and answers to HTML: structure, inline spans and, above all, escaping.

#include <gtest/gtest.h>

#include "legofeup/report/student_report.hpp"
#include "markdown.hpp"

namespace legofeup::report {
namespace {

TEST(Markdown, EscapesHtmlSoAScriptStaysText) {
    const std::string html = markdown_to_html("<script>alert('x')</script> & \"quotes\"");
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html,
              "<p>&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;quotes&quot;"
              "</p>\n");
}

TEST(Markdown, BlankLinesSeparateParagraphsAndLinesJoin) {
    EXPECT_EQ(markdown_to_html("first line\nsame paragraph\n\nsecond"),
              "<p>first line same paragraph</p>\n<p>second</p>\n");
}

TEST(Markdown, BulletAndNumberedLists) {
    EXPECT_EQ(markdown_to_html("Intro\n\n- one\n- two\n  continued\n\n1. first\n2) second"),
              "<p>Intro</p>\n<ul>\n<li>one</li>\n<li>two continued</li>\n</ul>\n"
              "<ol>\n<li>first</li>\n<li>second</li>\n</ol>\n");
}

TEST(Markdown, EmphasisStrongAndCode) {
    EXPECT_EQ(markdown_to_html("*a* **b** _c_ __d__ `x < y`"),
              "<p><em>a</em> <strong>b</strong> <em>c</em> <strong>d</strong> "
              "<code>x &lt; y</code></p>\n");
}

TEST(Markdown, UnderscoresInsideNamesAndLoneStarsStayText) {
    EXPECT_EQ(markdown_to_html("final_position_error_m > 2 * 0.1"),
              "<p>final_position_error_m &gt; 2 * 0.1</p>\n");
    EXPECT_EQ(markdown_to_html("`a*b*c` and \\*not\\*"), "<p><code>a*b*c</code> and *not*</p>\n");
}

TEST(Markdown, HeadingsSitBelowTheReportsOwn) {
    EXPECT_EQ(markdown_to_html("# Part\ntext"), "<h4>Part</h4>\n<p>text</p>\n");
}

TEST(Markdown, FencedCodeIsVerbatimAndEscaped) {
    EXPECT_EQ(markdown_to_html("```\nq11 = 1e-6 # *not emphasis*\n<b>\n```"),
              "<pre><code>q11 = 1e-6 # *not emphasis*\n&lt;b&gt;\n</code></pre>\n");
}

TEST(Markdown, LinksKeepSafeAddressesOnly) {
    EXPECT_EQ(markdown_to_html("[paper](https://example.org/a?b=1&c=2)"),
              "<p><a href=\"https://example.org/a?b=1&amp;c=2\">paper</a></p>\n");
    EXPECT_EQ(markdown_to_html("[click](javascript:alert)"), "<p>click</p>\n");
}

TEST(Markdown, PangoDialectUsesPangoTags) {
    EXPECT_EQ(markdown::render_inline("*a* **b** `c` [d](https://x.org) <e>", markdown::kPango),
              "<i>a</i> <b>b</b> <tt>c</tt> d (https://x.org) &lt;e&gt;");
}

}  // namespace
}  // namespace legofeup::report
