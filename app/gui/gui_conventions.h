// The workbench's desktop conventions, kept out of MainWindow: the file name a save dialog
// returns gets the extension of the kind it saves, the user guide is found where it was
// installed (or in the source tree of a build), and the keyboard shortcuts are listed from the
// menus themselves, so that the list cannot drift from what the keys do.
#pragma once

#include <QString>
#include <QStringList>

class QMenuBar;

namespace sonarcarve::gui {

/// `path` with `suffix` (".ply", no wildcard) appended unless it already ends with it or with
/// one of `also` (other spellings of the same kind: ".yml" for ".yaml"); case-insensitive.
QString withSuffix(const QString& path, const QString& suffix, const QStringList& also = {});

/// The user guide's first page: installed beside the program (share/doc/sonarcarve), or the
/// source tree's docs/ for a build that is not installed (build/PRESET/app). Empty if
/// neither exists.
QString userGuideFile();

/// Every menu action with a shortcut, as "Menu > Action: Keys" lines, in menu order.
QString shortcutList(const QMenuBar& bar);

}  // namespace sonarcarve::gui
