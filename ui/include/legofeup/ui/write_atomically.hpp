#pragma once
// Writing a file so that it is either complete or not there: through a temporary file
// renamed into place on success (QSaveFile). Exports, saved configurations and traces use it,
// so a full disk or a bad path never leaves half a file behind.

#include <QByteArray>
#include <QSaveFile>
#include <QString>

namespace legofeup::ui {

/// Writes `bytes` to `path`. Returns "" on success, else "cannot write PATH: reason".
inline QString write_atomically(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    }
    if (file.write(bytes) != bytes.size()) {
        const QString error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        file.cancelWriting();
        return error;
    }
    if (!file.commit()) {
        return QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    }
    return {};
}

}  // namespace legofeup::ui
