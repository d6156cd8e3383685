#include "markdown.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "legofeup/report/student_report.hpp"

namespace legofeup::report {
namespace markdown {
namespace {

bool is_blank(std::string_view line) {
    return line.find_first_not_of(" \t\r") == std::string_view::npos;
}

std::string_view trimmed(std::string_view line) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = line.find_last_not_of(" \t\r");
    return line.substr(first, last - first + 1);
}

// "# Title" → level 1 and "Title".
std::optional<std::pair<int, std::string_view>> heading(std::string_view line) {
    const std::string_view text = trimmed(line);
    int level = 0;
    while (static_cast<std::size_t>(level) < text.size()
           && text[static_cast<std::size_t>(level)] == '#') {
        ++level;
    }
    const auto after = static_cast<std::size_t>(level);
    if (level == 0 || level > 6 || after >= text.size() || text[after] != ' ') {
        return std::nullopt;
    }
    return std::pair{level, trimmed(text.substr(after))};
}

// "- item", "* item", "+ item" → "item".
std::optional<std::string_view> bullet_item(std::string_view line) {
    const std::string_view text = trimmed(line);
    if (text.size() >= 2 && (text[0] == '-' || text[0] == '*' || text[0] == '+')
        && text[1] == ' ') {
        return trimmed(text.substr(2));
    }
    return std::nullopt;
}

// "1. item" or "1) item" → "item".
std::optional<std::string_view> numbered_item(std::string_view line) {
    const std::string_view text = trimmed(line);
    std::size_t digits = 0;
    while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits])) != 0) {
        ++digits;
    }
    if (digits == 0 || digits + 1 >= text.size() || (text[digits] != '.' && text[digits] != ')')
        || text[digits + 1] != ' ') {
        return std::nullopt;
    }
    return trimmed(text.substr(digits + 2));
}

bool is_fence(std::string_view line) {
    return trimmed(line).substr(0, 3) == "```";
}

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = text.find('\n', start);
        if (end == std::string_view::npos) {
            lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

void append_words(std::string& text, std::string_view more) {
    if (!text.empty()) {
        text += ' ';
    }
    text += more;
}

bool is_word_character(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

// Only links a reader can safely follow: web and mail addresses and relative paths (no
// javascript: or data: URLs).
bool safe_url(std::string_view url) {
    const auto colon = url.find(':');
    if (colon == std::string_view::npos || url.find('/') < colon) {
        return true;
    }
    const std::string_view scheme = url.substr(0, colon);
    return scheme == "http" || scheme == "https" || scheme == "mailto";
}

class InlineRenderer {
  public:
    InlineRenderer(std::string_view text, const InlineDialect& dialect)
        : text_(text), dialect_(dialect) {}

    std::string render() {
        std::string out;
        std::size_t i = 0;
        while (i < text_.size()) {
            const char c = text_[i];
            if (c == '\\' && i + 1 < text_.size()
                && std::ispunct(static_cast<unsigned char>(text_[i + 1])) != 0) {
                out += escape(text_.substr(i + 1, 1));
                i += 2;
            } else if (c == '`') {
                i = code_span(i, out);
            } else if ((c == '*' || c == '_') && i + 1 < text_.size() && text_[i + 1] == c) {
                i = span(i, std::string(2, c), dialect_.strong_open, dialect_.strong_close, out);
            } else if (c == '*' || (c == '_' && (i == 0 || !is_word_character(text_[i - 1])))) {
                i = span(i, std::string(1, c), dialect_.emphasis_open, dialect_.emphasis_close,
                         out);
            } else if (c == '[') {
                i = link(i, out);
            } else {
                out += escape(text_.substr(i, 1));
                ++i;
            }
        }
        return out;
    }

  private:
    // `code`: its text verbatim (escaped), nothing inside is markup.
    std::size_t code_span(std::size_t start, std::string& out) const {
        const auto end = text_.find('`', start + 1);
        if (end == std::string_view::npos) {
            out += '`';
            return start + 1;
        }
        out += dialect_.code_open;
        out += escape(text_.substr(start + 1, end - start - 1));
        out += dialect_.code_close;
        return end + 1;
    }

    // *text*, **text**, _text_: the closing marker must follow text, and an underscore must
    // end a word (snake_case_names stay as they are).
    std::size_t span(std::size_t start, const std::string& marker, const char* open,
                     const char* close, std::string& out) const {
        const std::size_t inner = start + marker.size();
        std::size_t end = text_.find(marker, inner);
        while (end != std::string_view::npos) {
            const bool after_text = end > inner && text_[end - 1] != ' ';
            const std::size_t next = end + marker.size();
            const bool word_ends =
                marker[0] != '_' || next >= text_.size() || !is_word_character(text_[next]);
            if (after_text && word_ends) {
                break;
            }
            end = text_.find(marker, end + 1);
        }
        if (end == std::string_view::npos || text_[inner] == ' ') {
            out += escape(marker);
            return inner;
        }
        out += open;
        out += InlineRenderer(text_.substr(inner, end - inner), dialect_).render();
        out += close;
        return end + marker.size();
    }

    // [text](url)
    std::size_t link(std::size_t start, std::string& out) const {
        const auto close = text_.find("](", start);
        const auto end = close == std::string_view::npos ? close : text_.find(')', close + 2);
        if (end == std::string_view::npos
            || text_.substr(start, close - start).find('[', 1) != std::string_view::npos) {
            out += '[';
            return start + 1;
        }
        const std::string label =
            InlineRenderer(text_.substr(start + 1, close - start - 1), dialect_).render();
        const std::string_view url = trimmed(text_.substr(close + 2, end - close - 2));
        if (!safe_url(url)) {
            out += label;
        } else if (dialect_.html_links) {
            out += "<a href=\"" + escape(url) + "\">" + label + "</a>";
        } else {
            out += label + " (" + escape(url) + ")";
        }
        return end + 1;
    }

    std::string_view text_;
    const InlineDialect& dialect_;
};

}  // namespace

std::vector<Block> parse_blocks(std::string_view markdown) {
    std::vector<Block> blocks;
    bool open = false;  // whether the last block still takes lines
    const std::vector<std::string_view> lines = split_lines(markdown);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        if (is_blank(line)) {
            open = false;
            continue;
        }
        if (is_fence(line)) {
            Block code{Block::Kind::Code, 0, {}};
            for (++i; i < lines.size() && !is_fence(lines[i]); ++i) {
                code.texts.emplace_back(lines[i]);
            }
            blocks.push_back(std::move(code));
            open = false;
            continue;
        }
        if (const auto title = heading(line)) {
            blocks.push_back({Block::Kind::Heading, title->first, {std::string(title->second)}});
            open = false;
            continue;
        }
        const auto bullet = bullet_item(line);
        const auto numbered = bullet ? std::nullopt : numbered_item(line);
        if (bullet || numbered) {
            const Block::Kind kind = bullet ? Block::Kind::BulletList : Block::Kind::NumberedList;
            if (!open || blocks.back().kind != kind) {
                blocks.push_back({kind, 0, {}});
            }
            blocks.back().texts.emplace_back(bullet ? *bullet : *numbered);
            open = true;
            continue;
        }
        // Any other line continues the open paragraph or list item, or starts a paragraph.
        if (open) {
            append_words(blocks.back().texts.back(), trimmed(line));
            continue;
        }
        blocks.push_back({Block::Kind::Paragraph, 0, {std::string(trimmed(line))}});
        open = true;
    }
    return blocks;
}

std::string render_inline(std::string_view text, const InlineDialect& dialect) {
    return InlineRenderer(text, dialect).render();
}

std::string escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

}  // namespace markdown

std::string markdown_to_html(const std::string& text) {
    using markdown::Block;
    std::string html;
    for (const Block& block : markdown::parse_blocks(text)) {
        switch (block.kind) {
            case Block::Kind::Paragraph:
                html += "<p>" + markdown::render_inline(block.texts[0], markdown::kHtml) + "</p>\n";
                break;
            case Block::Kind::Heading: {
                // Headings inside a lesson's text sit below the report's own h1 … h3.
                const std::string tag = "h" + std::to_string(std::min(block.level + 3, 6));
                html += "<" + tag + ">" + markdown::render_inline(block.texts[0], markdown::kHtml)
                        + "</" + tag + ">\n";
                break;
            }
            case Block::Kind::BulletList:
            case Block::Kind::NumberedList: {
                const char* tag = block.kind == Block::Kind::BulletList ? "ul" : "ol";
                html += std::string("<") + tag + ">\n";
                for (const std::string& item : block.texts) {
                    html += "<li>" + markdown::render_inline(item, markdown::kHtml) + "</li>\n";
                }
                html += std::string("</") + tag + ">\n";
                break;
            }
            case Block::Kind::Code:
                html += "<pre><code>";
                for (const std::string& line : block.texts) {
                    html += markdown::escape(line) + "\n";
                }
                html += "</code></pre>\n";
                break;
        }
    }
    return html;
}

}  // namespace legofeup::report
