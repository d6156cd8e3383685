#pragma once
// Numbers as students type them ("1e-9", "0.0001", "-3.5") and as the panel shows them: the
// shortest text that reads back to the same double, as in the TOML files.

#include <QString>
#include <optional>

namespace legofeup::ui {

/// The number `text` spells exactly (surrounding spaces allowed), or nullopt for anything
/// else: empty text, trailing garbage ("1e-9x"), a comma for a point, nan or inf.
std::optional<double> parse_number(const QString& text);

/// The shortest exact text of `value` ("1e-07", "0.12", "3").
QString number_text(double value);

}  // namespace legofeup::ui
