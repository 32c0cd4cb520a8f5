#include "gui_conventions.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>

namespace sonarcarve::gui {
namespace {

// "&File" -> "File"; the ellipsis of a dialog's action goes too.
QString plainText(QString text) {
  text.remove('&');
  if (text.endsWith(QStringLiteral("…"))) {
    text.chop(1);
  }
  return text;
}

void listShortcuts(const QMenu& menu, const QString& path, QStringList& lines) {
  for (const QAction* action : menu.actions()) {
    if (action->menu() != nullptr) {
      listShortcuts(*action->menu(), path + " > " + plainText(action->text()), lines);
    } else if (!action->shortcut().isEmpty()) {
      lines << QStringLiteral("%1 > %2: %3")
                   .arg(path, plainText(action->text()),
                        action->shortcut().toString(QKeySequence::NativeText));
    }
  }
}

}  // namespace

QString withSuffix(const QString& path, const QString& suffix, const QStringList& also) {
  if (path.isEmpty() || path.endsWith(suffix, Qt::CaseInsensitive)) {
    return path;
  }
  for (const QString& other : also) {
    if (path.endsWith(other, Qt::CaseInsensitive)) {
      return path;
    }
  }
  return path + suffix;
}

QString userGuideFile() {
  // Installed: bin/sonarcarve and share/doc/sonarcarve; built: build/PRESET/app/sonarcarve.
  const QDir program(QCoreApplication::applicationDirPath());
  for (const char* relative :
       {"../share/doc/sonarcarve/user-guide/README.md", "../../../docs/user-guide/README.md"}) {
    const QString candidate = QDir::cleanPath(program.filePath(relative));
    if (QFileInfo(candidate).isFile()) {
      return candidate;
    }
  }
  return {};
}

QString shortcutList(const QMenuBar& bar) {
  QStringList lines;
  for (const QAction* action : bar.actions()) {
    if (action->menu() != nullptr) {
      listShortcuts(*action->menu(), plainText(action->text()), lines);
    }
  }
  return lines.join('\n');
}

}  // namespace sonarcarve::gui
