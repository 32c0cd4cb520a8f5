#include "vtk_gl_widget.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QWheelEvent>

// GL enums without including GL headers next to VTK's GLEW (the notes: never both).
namespace {
constexpr unsigned kGlColorBufferBit = 0x00004000;
constexpr unsigned kGlDrawFramebuffer = 0x8CA9;
}  // namespace

namespace sonarcarve::widgets {

VtkGlWidget::VtkGlWidget(QWidget* parent) : QOpenGLWidget(parent) {
  window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  interactor_ = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  window_->SetReadyForRendering(false);
  window_->SetForceMaximumHardwareLineWidth(1);
  window_->SetOwnContext(false);
  window_->SetFrameBlitModeToNoBlit();
  window_->SetMultiSamples(0);
  window_->AddRenderer(renderer_);
  interactor_->SetRenderWindow(window_);
  interactor_->EnableRenderOff();  // Qt decides when to paint
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor_->SetInteractorStyle(style);
  bindObservers();
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(200, 200);
}

VtkGlWidget::~VtkGlWidget() {
  makeCurrent();
  window_->Finalize();
  doneCurrent();
}

void VtkGlWidget::setDefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(0);
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

vtkRenderer* VtkGlWidget::renderer() const {
  return renderer_;
}
vtkGenericOpenGLRenderWindow* VtkGlWidget::renderWindow() const {
  return window_;
}

void VtkGlWidget::bindObservers() {
  // "Make current": make the widget's context current on its surface, without
  // QOpenGLWidget::makeCurrent(), which would rebind Qt's framebuffer behind VTK's back.
  auto make_current = vtkSmartPointer<vtkCallbackCommand>::New();
  make_current->SetClientData(this);
  make_current->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* w = static_cast<VtkGlWidget*>(self);
    if (QOpenGLContext* ctx = w->context()) {
      ctx->makeCurrent(ctx->surface());
    }
  });
  window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, make_current);

  auto is_current = vtkSmartPointer<vtkCallbackCommand>::New();
  is_current->SetClientData(this);
  is_current->SetCallback([](vtkObject*, unsigned long, void* self, void* answer) {
    auto* w = static_cast<VtkGlWidget*>(self);
    QOpenGLContext* ctx = w->context();
    *static_cast<bool*>(answer) = ctx != nullptr && QOpenGLContext::currentContext() == ctx;
  });
  window_->AddObserver(vtkCommand::WindowIsCurrentEvent, is_current);

  auto schedule = vtkSmartPointer<vtkCallbackCommand>::New();
  schedule->SetClientData(this);
  schedule->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* w = static_cast<VtkGlWidget*>(self);
    if (!w->painting_) {
      w->update();
    }
  });
  window_->AddObserver(vtkCommand::WindowFrameEvent, schedule);
  interactor_->AddObserver(vtkCommand::RenderEvent, schedule);
}

void VtkGlWidget::initializeGL() {
  window_->SetReadyForRendering(true);
  window_->OpenGLInitContext();
  window_->GetState()->Reset();
}

void VtkGlWidget::resizeGL(int w, int h) {
  const double ratio = devicePixelRatioF();
  interactor_->UpdateSize(static_cast<int>(w * ratio), static_cast<int>(h * ratio));
}

void VtkGlWidget::paintGL() {
  painting_ = true;
  vtkOpenGLState* state = window_->GetState();
  state->Reset();
  state->Push();
  window_->Render();
  const int w = static_cast<int>(width() * devicePixelRatioF());
  const int h = static_cast<int>(height() * devicePixelRatioF());
  state->vtkglBindFramebuffer(kGlDrawFramebuffer, defaultFramebufferObject());
  window_->BlitDisplayFramebuffer(0, 0, 0, w, h, 0, 0, w, h, kGlColorBufferBit, 0x2600);
  // The blit copies VTK's alpha; the widget must be opaque.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(kGlColorBufferBit);
  state->Pop();
  painting_ = false;
}

void VtkGlWidget::forwardMouse(QMouseEvent* event, unsigned long vtk_event) {
  const double ratio = devicePixelRatioF();
  const QPointF p = event->position();
  interactor_->SetEventInformationFlipY(
      static_cast<int>(p.x() * ratio), static_cast<int>(p.y() * ratio),
      event->modifiers() & Qt::ControlModifier, event->modifiers() & Qt::ShiftModifier);
  interactor_->InvokeEvent(vtk_event, event);
  update();
}

// The VTK event of a button press or release; 0 for buttons VTK does not use.
static unsigned long buttonEvent(Qt::MouseButton button, bool press) {
  switch (button) {
    case Qt::LeftButton:
      return press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
      return press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
      return press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    default:
      return 0;
  }
}

void VtkGlWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) {
    press_position_ = event->position().toPoint();
  }
  if (const unsigned long e = buttonEvent(event->button(), true)) {
    forwardMouse(event, e);
  }
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (const unsigned long e = buttonEvent(event->button(), false)) {
    forwardMouse(event, e);
  }
  constexpr int kClickSlop_px = 4;
  if (event->button() == Qt::LeftButton &&
      (event->position().toPoint() - press_position_).manhattanLength() <= kClickSlop_px) {
    emit clicked(press_position_);
  }
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* event) {
  forwardMouse(event, vtkCommand::MouseMoveEvent);
}

void VtkGlWidget::wheelEvent(QWheelEvent* event) {
  const double ratio = devicePixelRatioF();
  const QPointF p = event->position();
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * ratio),
                                        static_cast<int>(p.y() * ratio));
  interactor_->InvokeEvent(event->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                       : vtkCommand::MouseWheelBackwardEvent,
                           event);
  update();
}

}  // namespace sonarcarve::widgets
