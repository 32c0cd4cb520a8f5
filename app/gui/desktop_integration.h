// The workbench on the desktop: its icon and the desktop entry its windows belong to
// (packaging/: io.github.sonarcarve.SonarCarve.desktop, icon "sonarcarve" in hicolor).
#pragma once

#include <QIcon>

namespace sonarcarve::gui {

/// The desktop entry's id, also the AppStream component id.
inline constexpr const char* kDesktopFileName = "io.github.sonarcarve.SonarCarve";

/// The application icon: "sonarcarve" from the icon theme (the package installs it to
/// hicolor; <exe dir>/../share/icons is searched too, for a prefix that is not on
/// XDG_DATA_DIRS), else the PNGs compiled into the program (a build tree, or a system without
/// the icon). Needs a QGuiApplication.
QIcon applicationIcon();

/// Sets the application's window icon and desktop file name. Call after QApplication.
void setUpDesktopIntegration();

}  // namespace sonarcarve::gui
