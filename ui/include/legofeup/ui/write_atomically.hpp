#pragma once
// Writing a file so that it is either complete or not there: the GUI's side of the one
// atomic writer (legofeup/fileio/atomic_file.hpp: a temporary file beside the target,
// fsync'ed and renamed into place). Exports, saved configurations and traces use it, so a
// full disk or a bad path never leaves half a file behind.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <string_view>

#include "legofeup/fileio/atomic_file.hpp"

namespace legofeup::ui {

/// Writes `bytes` to `path`. Returns "" on success, else "cannot write PATH: what failed:
/// reason" (fileio::WriteError's text).
inline QString write_atomically(const QString& path, const QByteArray& bytes) {
    try {
        fileio::write_file_atomically(
            QFile::encodeName(path).toStdString(),
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const fileio::WriteError& error) {
        return QString::fromStdString(error.what());
    }
    return {};
}

}  // namespace legofeup::ui
