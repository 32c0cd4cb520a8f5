// VtkGlWidget: a Qt6 QOpenGLWidget that hosts a VTK render window. Debian 12's VTK Qt module
// is built for Qt5 only, so SonarCarve hosts VTK itself (docs: ../shared/notes on Qt6 + VTK):
// VTK renders into its own framebuffer in the widget's GL context, and paintGL() blits that
// into the widget's framebuffer. Mouse and wheel events are forwarded to a VTK interactor
// (trackball camera). Call setDefaultSurfaceFormat() before the QApplication is created.
// GUI thread only.
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <QOpenGLWidget>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;

namespace sonarcarve::widgets {

class VtkGlWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkGlWidget(QWidget* parent = nullptr);
  ~VtkGlWidget() override;

  /// OpenGL 3.2 core, double buffered, RGBA8 with depth, no multisampling (4x costs 3 to 6
  /// times more with Mesa's software renderer).
  static void setDefaultSurfaceFormat();

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  /// Schedules a repaint (coalesced by Qt).
  void requestRender() { update(); }

 signals:
  /// The left button went down and up without the mouse moving (a click, not a drag), at
  /// `position` in the widget.
  void clicked(QPoint position);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void resizeGL(int w, int h) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void forwardMouse(QMouseEvent* event, unsigned long vtk_event);
  void bindObservers();

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkRenderer> renderer_;
  bool painting_ = false;
  QPoint press_position_;
};

}  // namespace sonarcarve::widgets
