#include "desktop_integration.h"

#include <QCoreApplication>
#include <QDir>
#include <QGuiApplication>

namespace sonarcarve::gui {

QIcon applicationIcon() {
  const QString prefix_icons =
      QDir::cleanPath(QCoreApplication::applicationDirPath() + "/../share/icons");
  QStringList paths = QIcon::themeSearchPaths();
  if (QDir(prefix_icons).exists() && !paths.contains(prefix_icons)) {
    paths.prepend(prefix_icons);
    QIcon::setThemeSearchPaths(paths);
  }
  QIcon compiled_in;
  for (const int size : {16, 32, 48, 64, 128, 256}) {
    compiled_in.addFile(QString(":/sonarcarve/icons/sonarcarve-%1.png").arg(size));
  }
  return QIcon::fromTheme("sonarcarve", compiled_in);
}

void setUpDesktopIntegration() {
  QGuiApplication::setDesktopFileName(kDesktopFileName);
  QGuiApplication::setWindowIcon(applicationIcon());
}

}  // namespace sonarcarve::gui
