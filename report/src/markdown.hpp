#pragma once
// The small Markdown the lessons are written in — paragraphs, headings, bullet and numbered
// lists, fenced code, *emphasis*, **strong**, `code` and [links](https://…) — parsed once
// into blocks and rendered either as HTML (the report's HTML) or as Pango markup (its PDF).
// Everything typed is escaped: a student's "<script>" stays text.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace legofeup::report::markdown {

struct Block {
    enum class Kind : std::uint8_t { Paragraph, Heading, BulletList, NumberedList, Code };
    Kind kind = Kind::Paragraph;
    int level = 0;  ///< headings: 1 … 6
    /// Paragraphs and headings: one text; lists: one text per item; code: the lines verbatim.
    std::vector<std::string> texts;
};

std::vector<Block> parse_blocks(std::string_view markdown);

/// The tags inline spans become in one output language.
struct InlineDialect {
    const char* emphasis_open;
    const char* emphasis_close;
    const char* strong_open;
    const char* strong_close;
    const char* code_open;
    const char* code_close;
    bool html_links;  ///< <a href>; otherwise the link text followed by "(url)"
};

inline constexpr InlineDialect kHtml{"<em>",   "</em>",   "<strong>", "</strong>",
                                     "<code>", "</code>", true};
inline constexpr InlineDialect kPango{"<i>", "</i>", "<b>", "</b>", "<tt>", "</tt>", false};

/// One block's text with its inline spans, escaped for `dialect`.
std::string render_inline(std::string_view text, const InlineDialect& dialect);

/// &, <, >, " and ' as entities: safe in HTML text, attributes and Pango markup.
std::string escape(std::string_view text);

}  // namespace legofeup::report::markdown
