// The 3D view's inspection tools on data made here, under Xvfb (the view needs OpenGL): the
// scale bar follows the zoom, the clip box and the cross-section draw only what lies in them,
// the mesh is coloured by the chosen value, a result's layers built on a worker are shown as
// they are, picks are marked, and a map past the view's budget of points is held coarser.
#include <QDoubleSpinBox>
#include <QtTest>
#include <cmath>
#include <thread>

#include "clip_dialog.h"
#include "map_view.h"
#include "scale_bar.h"
#include "vtk_gl_widget.h"

using sonarcarve::widgets::ClipDialog;
using sonarcarve::widgets::MapLod;
using sonarcarve::widgets::MapView;
using sonarcarve::widgets::MapViewBlock;
using sonarcarve::widgets::ScaleBar;
using sonarcarve::widgets::ViewClip;

namespace {

constexpr int kSide = 21;  // points along each axis, every 0.1 m from 0 to 2 m

// A cube of points split into blocks along north, valued by their index.
std::vector<MapViewBlock> cubeBlocks() {
  std::vector<MapViewBlock> blocks(kSide);
  for (int n = 0; n < kSide; ++n) {
    blocks[static_cast<std::size_t>(n)].block = static_cast<std::size_t>(n);
    for (int e = 0; e < kSide; ++e) {
      for (int d = 0; d < kSide; ++d) {
        blocks[static_cast<std::size_t>(n)].points.emplace_back(0.1f * n, 0.1f * e, 0.1f * d);
        blocks[static_cast<std::size_t>(n)].values.push_back(static_cast<float>(n + e + d));
      }
    }
  }
  return blocks;
}

std::size_t countInside(const std::vector<MapViewBlock>& blocks, const ViewClip& clip) {
  std::size_t n = 0;
  for (const auto& b : blocks) {
    for (const auto& p : b.points) {
      n += clip.contains(p) ? 1 : 0;
    }
  }
  return n;
}

bool allInside(const std::vector<Eigen::Vector3f>& points, const ViewClip& clip) {
  return std::all_of(points.begin(), points.end(),
                     [&](const Eigen::Vector3f& p) { return clip.contains(p); });
}

// Two upright squares (2 m wide in east, 0.5 m tall in depth, wound to face north) of two triangles
// each, one from depth `d0` and one from `d1`, 4 m apart in east.
sonarcarve::Mesh twoSquares(float d0, float d1) {
  sonarcarve::Mesh mesh;
  for (float d : {d0, d1}) {
    const float e0 = d == d0 ? -3.0f : 1.0f;
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const auto& [e, dd] : {std::pair{0.0f, 0.0f}, {2.0f, 0.0f}, {2.0f, 0.5f}, {0.0f, 0.5f}}) {
      mesh.vertices.emplace_back(0.0f, e0 + e, d + dd);
      mesh.normals.emplace_back(1.0f, 0.0f, 0.0f);  // as the winding has it
      mesh.intensity.push_back(d == d0 ? 10.0f : 1000.0f);
    }
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first, first + 2, first + 3});
  }
  return mesh;
}

double metresPerPixelMeasured(MapView& view) {
  // One metre across the view at the focal point, on the screen.
  const sonarcarve::CameraState c = view.cameraState();
  const Eigen::Vector3d focal = c.focal_point;
  const Eigen::Vector3d direction = (focal - c.position).normalized();
  const Eigen::Vector3d right = direction.cross(c.view_up).normalized();
  const QPoint a = view.screenPositionOf(focal - 0.5 * right);
  const QPoint b = view.screenPositionOf(focal + 0.5 * right);
  return 1.0 / QLineF(a, b).length();
}

bool isRound(double metres) {
  const double mantissa = metres / std::pow(10.0, std::floor(std::log10(metres) + 1e-9));
  return std::abs(mantissa - 1.0) < 1e-6 || std::abs(mantissa - 2.0) < 1e-6 ||
         std::abs(mantissa - 5.0) < 1e-6;
}

}  // namespace

class InspectionTest : public QObject {
  Q_OBJECT

 private slots:
  void roundLengths() {
    QCOMPARE(ScaleBar::roundLength(1.3), 1.0);
    QCOMPARE(ScaleBar::roundLength(0.7), 0.5);
    QCOMPARE(ScaleBar::roundLength(0.5), 0.5);
    QCOMPARE(ScaleBar::roundLength(37.0), 20.0);
    QCOMPARE(ScaleBar::roundLength(0.0), 0.0);
    ScaleBar bar;
    bar.setMetresPerPixel(0.004);  // 120 px = 0.48 m: a 20 cm bar of 50 px
    QCOMPARE(bar.text(), QString("20 cm"));
    QCOMPARE(bar.barPixels(), 50);
  }

  // The bar is a round length, as long on the screen as that length at the focal point, and
  // follows the zoom, in perspective and in parallel projection.
  void scaleBarFollowsTheZoom() {
    MapView view;
    view.resize(900, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.applyBlocks(cubeBlocks());
    view.flush();
    QTest::qWait(50);
    const ScaleBar& bar = view.scaleBar();
    for (bool parallel : {false, true}) {
      view.setOrthographic(parallel);
      for (double closer : {1.0, 2.0, 5.0}) {
        sonarcarve::CameraState c = view.cameraState();
        c.position = c.focal_point + (c.position - c.focal_point) / closer;
        c.parallel_scale /= closer;
        view.setCameraState(c);
        const double measured = metresPerPixelMeasured(view);
        QVERIFY2(std::abs(bar.metresPerPixel() / measured - 1.0) < 0.02,
                 qPrintable(QString("%1 vs %2").arg(bar.metresPerPixel()).arg(measured)));
        QVERIFY(bar.isVisible());
        QVERIFY(isRound(bar.lengthMetres()));
        QVERIFY(bar.barPixels() >= 2 * ScaleBar::kMaxBarPixels / 5 - 1);
        QVERIFY(bar.barPixels() <= ScaleBar::kMaxBarPixels);
      }
    }
  }

  // Only the points inside the box and the slab are drawn, on the map and the surface; the
  // mesh keeps the triangles whose centre is inside; an inactive clip draws everything again.
  void clipBoxAndCrossSectionDrawOnlyWhatIsInside() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const auto blocks = cubeBlocks();
    view.applyBlocks(blocks);
    view.flush();
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide * kSide});

    ViewClip clip;
    clip.box =
        Eigen::AlignedBox3d(Eigen::Vector3d(0.45, 0.45, 0.45), Eigen::Vector3d(1.55, 1.05, 2.5));
    view.setClip(clip);
    QCOMPARE(view.drawnPointCount(), std::size_t{11 * 6 * 16});
    QCOMPARE(view.drawnPointCount(), countInside(blocks, clip));
    QVERIFY(allInside(view.drawnPoints(), clip));

    clip.section = ViewClip::Section{ViewClip::Axis::East, 0.8, 0.15};  // east 0.8 only
    view.setClip(clip);
    QCOMPARE(view.drawnPointCount(), std::size_t{11 * 16});
    QVERIFY(allInside(view.drawnPoints(), clip));
    for (const auto& p : view.drawnPoints()) {
      QVERIFY(std::abs(p.y() - 0.8f) < 1e-4f);
    }

    ViewClip section_only;  // a horizontal slice at 1 m depth
    section_only.section = ViewClip::Section{ViewClip::Axis::Down, 1.0, 0.05};
    view.setClip(section_only);
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide});

    MapViewBlock surface;
    for (const auto& b : blocks) {
      surface.points.insert(surface.points.end(), b.points.begin(), b.points.end());
      surface.values.insert(surface.values.end(), b.values.begin(), b.values.end());
    }
    view.setSurface(surface);
    view.setLayer(MapView::Layer::Surface);
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide});
    QVERIFY(allInside(view.drawnPoints(), section_only));

    view.setMesh(twoSquares(0.0f, 10.0f));
    view.setLayer(MapView::Layer::Mesh);
    QCOMPARE(view.drawnTriangleCount(), std::size_t{0});  // neither square at 1 m depth
    ViewClip shallow;
    shallow.box = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(10, 10, 1));
    view.setClip(shallow);
    QCOMPARE(view.drawnTriangleCount(), std::size_t{2});

    view.setClip(ViewClip{});
    QCOMPARE(view.drawnTriangleCount(), std::size_t{4});
    view.setLayer(MapView::Layer::Map);
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide * kSide});
  }

  // While carving, blocks changed within the last kSettleFrames frames are drawn apart
  // (translucent) from the settled ones; when the run ends everything is settled.
  void provisionalVoxelsAreDrawnApart() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setLive(true);
    auto blocks = cubeBlocks();
    for (auto& b : blocks) {
      b.frames_done = 4;
    }
    view.applyBlocks(blocks);
    view.flush();
    QCOMPARE(view.provisionalPointCount(), std::size_t{kSide * kSide * kSide});
    QCOMPARE(view.settledPointCount(), std::size_t{0});
    QVERIFY(!view.legendText().isEmpty());
    // Frames 5 to 12 changed the blocks north of 1 m only.
    std::vector<MapViewBlock> later(blocks.begin() + 11, blocks.end());
    for (auto& b : later) {
      b.frames_done = 4 + MapView::kSettleFrames;
    }
    view.applyBlocks(later);
    view.flush();
    QCOMPARE(view.provisionalPointCount(), std::size_t{10 * kSide * kSide});
    QCOMPARE(view.settledPointCount(), std::size_t{11 * kSide * kSide});
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide * kSide});
    view.setLive(false);
    view.flush();
    QCOMPARE(view.provisionalPointCount(), std::size_t{0});
    QCOMPARE(view.settledPointCount(), std::size_t{kSide * kSide * kSide});
  }

  // Past its budget of points the view holds the blocks changed longest ago coarser: it holds
  // at most the budget, still counts every voxel, draws a point of every block, and a pick on
  // a coarser point says it is the mean of several voxels. Within the budget it holds them all.
  void mapPastTheBudgetIsHeldCoarser() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setVoxelSize(0.1);  // the cube's spacing
    constexpr std::size_t kBudget = 2000;
    view.setMapPointBudget(kBudget);
    auto blocks = cubeBlocks();  // a block per north slice, the southernmost sent first
    for (std::size_t n = 0; n < blocks.size(); ++n) {
      blocks[n].frames_done = 4 * n;
      view.applyBlocks({blocks[n]});
    }
    view.flush();
    QCOMPARE(view.mapPointCount(), std::size_t{kSide * kSide * kSide});
    QVERIFY(view.heldMapPointCount() <= kBudget);
    // Fewer voxels than kMaxDrawnMapPoints: every point held is drawn.
    QCOMPARE(view.drawnPointCount(), view.heldMapPointCount());
    const std::vector<Eigen::Vector3f> drawn = view.drawnPoints();
    for (int n = 0; n < kSide; ++n) {
      QVERIFY2(
          std::any_of(drawn.begin(), drawn.end(),
                      [&](const Eigen::Vector3f& p) { return std::abs(p.x() - 0.1f * n) < 0.05f; }),
          qPrintable(QString("slice %1 not drawn").arg(n)));
    }
    // The southernmost slice, sent first, is the coarsest and the nearest to the camera.
    view.viewFromSide();
    const auto front = std::min_element(
        drawn.begin(), drawn.end(),
        [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return a.x() < b.x(); });
    const QString text = view.pickAt(view.screenPositionOf(front->cast<double>()));
    QVERIFY2(text.startsWith("N 0.00") && text.contains("voxels)"), qPrintable(text));

    view.setMapPointBudget(MapLod::kDefaultMaxPoints);
    view.clearMap();
    view.applyBlocks(cubeBlocks());
    view.flush();
    QCOMPARE(view.heldMapPointCount(), std::size_t{kSide * kSide * kSide});
    QCOMPARE(view.drawnPointCount(), std::size_t{kSide * kSide * kSide});
  }

  // The depth scale spans the map's depths, whether every block is settled or some are
  // provisional (the empty part's 0 to 1 is not in it).
  void depthScaleSpansTheMapsDepths() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setColourBy(MapView::ColourBy::Depth);
    auto blocks = cubeBlocks();
    for (auto& b : blocks) {
      for (auto& p : b.points) {
        p.z() += 10.0f;
      }
    }
    view.applyBlocks(blocks);
    view.flush();
    QCOMPARE(view.legendText(), QString("depth (m): 10.00 to 12.00"));
    view.setLive(true);
    view.flush();
    QCOMPARE(view.provisionalPointCount(), std::size_t{kSide * kSide * kSide});
    QCOMPARE(view.legendText(), QString("depth (m): 10.00 to 12.00"));
  }

  // The dialog starts from the clip in force and gives back what was typed.
  void clipDialogRoundTrips() {
    ViewClip clip;
    clip.box = Eigen::AlignedBox3d(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6));
    clip.section = ViewClip::Section{ViewClip::Axis::Down, 4.5, 0.2};
    ClipDialog dialog(clip, Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
    ViewClip back = dialog.clip();
    QVERIFY(back.box && back.box->isApprox(*clip.box));
    QVERIFY(back.section && back.section->axis == ViewClip::Axis::Down);
    QCOMPARE(back.section->position_m, 4.5);
    dialog.findChild<QDoubleSpinBox*>("max_1")->setValue(7.5);
    back = dialog.clip();
    QCOMPARE(back.box->max().y(), 7.5);
  }

  // The mesh takes the colouring of the points: by depth its shallow square is the colour
  // table's low end (violet) and its deep one the high end (yellow); the key says so.
  void meshIsColouredByTheChosenValue() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const sonarcarve::Mesh mesh = twoSquares(0.0f, 2.0f);
    view.setMesh(mesh, {0.0f, 0.0f, 0.0f, 0.0f, 0.1f, 0.1f, 0.1f, 0.1f});
    view.setLayer(MapView::Layer::Mesh);
    view.viewFromSide();  // from the south: east to the right, down downwards
    view.setColourBy(MapView::ColourBy::Depth);
    QCOMPARE(view.legendText(), QString("depth (m): 0.00 to 2.50"));
    QImage image = view.grabImage();
    const QColor shallow = image.pixelColor(view.screenPositionOf({0.0, -2.0, 0.25}));
    const QColor deep = image.pixelColor(view.screenPositionOf({0.0, 2.0, 2.25}));
    QVERIFY2(shallow.blue() > shallow.green() && deep.green() > deep.blue(),
             qPrintable(QString("shallow %1, deep %2").arg(shallow.name(), deep.name())));
    view.setColourBy(MapView::ColourBy::Intensity);
    QVERIFY(view.legendText().startsWith("intensity (counts): 0 to "));
    view.setColourBy(MapView::ColourBy::Error);
    QCOMPARE(view.legendText(), QString("error vs ground truth (cm): 0.00 to 10.00"));
    image = view.grabImage();
    const QColor on_truth = image.pixelColor(view.screenPositionOf({0.0, -2.0, 0.25}));
    const QColor off_truth = image.pixelColor(view.screenPositionOf({0.0, 2.0, 2.25}));
    QVERIFY2(on_truth.green() > on_truth.red() && off_truth.red() > off_truth.green(),
             qPrintable(QString("on %1, off %2").arg(on_truth.name(), off_truth.name())));
  }

  // A run's surface and mesh layers are built off the GUI thread (MapView::prepareResult on a
  // worker); showing them builds nothing on the GUI thread when the view's colouring and clip
  // are those they were built for, and rebuilds them when the user changed either meanwhile.
  void aResultPreparedOnAWorkerIsShownWithoutRebuilding() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const auto blocks = cubeBlocks();
    MapViewBlock surface;
    for (const auto& b : blocks) {
      surface.points.insert(surface.points.end(), b.points.begin(), b.points.end());
      surface.values.insert(surface.values.end(), b.values.begin(), b.values.end());
    }
    const auto prepare = [&](MapView::ColourBy by) {
      MapView::PreparedResult prepared;
      std::thread worker([&] {
        prepared = MapView::prepareResult(surface, sonarcarve::widgets::meshData(twoSquares(0, 2)),
                                          by, ViewClip{});
      });
      worker.join();
      return prepared;
    };
    view.setColourBy(MapView::ColourBy::Depth);
    const std::size_t built = view.resultLayersBuiltHere();
    view.setResult(prepare(MapView::ColourBy::Depth));
    QCOMPARE(view.resultLayersBuiltHere(), built);
    view.setLayer(MapView::Layer::Surface);
    QCOMPARE(view.drawnPointCount(), surface.points.size());
    QCOMPARE(view.legendText(), QString("depth (m): 0.00 to 2.00"));
    view.setLayer(MapView::Layer::Mesh);
    QCOMPARE(view.drawnTriangleCount(), std::size_t{4});

    // Prepared for intensity, shown after the user chose depth: rebuilt here, by depth.
    view.setResult(prepare(MapView::ColourBy::Intensity));
    QCOMPARE(view.resultLayersBuiltHere(), built + 2);
    view.setLayer(MapView::Layer::Surface);
    QCOMPARE(view.legendText(), QString("depth (m): 0.00 to 2.00"));
    QCOMPARE(view.drawnPointCount(), surface.points.size());
  }

  // A click that picks a point marks it; a second click draws the line of the distance between
  // the two; a third moves both on; clearing removes the marks.
  void picksAreMarkedInTheView() {
    MapView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // A wall of points across east and down, seen from the south: no point hides another.
    MapViewBlock wall;
    for (int e = 0; e < kSide; ++e) {
      for (int d = 0; d < kSide; ++d) {
        wall.points.emplace_back(0.0f, 0.1f * e, 0.1f * d);
        wall.values.push_back(static_cast<float>(e + d));
      }
    }
    view.setSurface(wall);
    view.setLayer(MapView::Layer::Surface);
    view.viewFromSide();
    QVERIFY(view.pickMarkerPoints().empty());
    QVERIFY(view.pickLinePoints().empty());
    auto* gl = view.findChild<sonarcarve::widgets::VtkGlWidget*>();
    QVERIFY(gl);
    QSignalSpy picked(&view, &MapView::pointPicked);
    const Eigen::Vector3d a(0.0, 0.3, 0.4);
    const Eigen::Vector3d b(0.0, 1.6, 1.2);
    const Eigen::Vector3d c(0.0, 1.0, 1.9);
    const auto near = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
      return (p - q).norm() < 0.05;  // half the points' spacing
    };
    QTest::mouseClick(gl, Qt::LeftButton, {}, view.screenPositionOf(a));
    QCOMPARE(picked.count(), 1);
    QCOMPARE(view.pickMarkerPoints().size(), std::size_t{1});
    QVERIFY(near(view.pickMarkerPoints().front(), a));
    QVERIFY(view.pickLinePoints().empty());  // one pick: no distance yet

    QTest::mouseClick(gl, Qt::LeftButton, {}, view.screenPositionOf(b));
    QCOMPARE(picked.count(), 2);
    QCOMPARE(view.pickMarkerPoints().size(), std::size_t{1});
    QVERIFY(near(view.pickMarkerPoints().front(), b));
    const auto line = view.pickLinePoints();
    QCOMPARE(line.size(), std::size_t{2});
    QVERIFY(near(line[0], a) && near(line[1], b));

    QTest::mouseClick(gl, Qt::LeftButton, {}, view.screenPositionOf(c));
    QVERIFY(near(view.pickMarkerPoints().front(), c));
    QVERIFY(near(view.pickLinePoints()[0], b) && near(view.pickLinePoints()[1], c));

    // The marker is drawn: magenta at the pick, on top of the viridis points.
    const QColor marker = view.grabImage().pixelColor(view.screenPositionOf(c) + QPoint(3, 0));
    QVERIFY2(marker.red() > 200 && marker.blue() > 150 && marker.green() < 120,
             qPrintable(marker.name()));

    view.clearPicks();
    QVERIFY(view.pickMarkerPoints().empty());
    QVERIFY(view.pickLinePoints().empty());
  }
};

int main(int argc, char** argv) {
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  InspectionTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "inspection_test.moc"
