// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Drawing a Mobius_mesh in CGAL's Basic_viewer_qt, in the manner of
// CGAL::draw(): one colour per side, so that a one-sided surface shows itself.
// Needs CGAL's Qt5 component (Debian libcgal-qt5-dev): link with
// CGAL::CGAL_Basic_viewer, which defines CGAL_USE_BASIC_VIEWER. Without it,
// draw() and save_screenshot() say so and do nothing, as CGAL::draw() does.

#ifndef CGAL_EXT_DRAW_MOBIUS_MESH_H
#define CGAL_EXT_DRAW_MOBIUS_MESH_H

#include <CGAL_ext/IO/internal/Atomic_output_file.h>
#include <CGAL_ext/Mobius_mesh.h>
#include <CGAL_ext/Mobius_mesh/two_sided_scene.h>
#include <CGAL_ext/Named_parameters.h>
#include <CGAL_ext/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <type_traits>

#ifdef CGAL_USE_BASIC_VIEWER
#include <CGAL/Qt/Basic_viewer_qt.h>
#include <CGAL/Qt/init_ogl_context.h>

#include <QApplication>
#include <QEventLoop>
#include <QTimer>
#include <functional>
#include <memory>
#endif

namespace CGAL_ext {

/// \ingroup PkgMobiusMeshDrawing
/// The picture `save_screenshot()` takes.
struct Screenshot_settings
{
  int width = 800;  ///< in pixels
  int height = 600; ///< in pixels
  /// The direction the camera looks in; the whole mesh is in view. The
  /// default looks down on the mesh from above and to the side.
  std::array<double, 3> view_direction{{-1.0, -0.6, -1.2}};
  /// The direction that is up in the picture (as far as it is not along the
  /// view direction); the z axis, as the library's generators build surfaces.
  std::array<double, 3> up_vector{{0.0, 0.0, 1.0}};
};

#if defined(CGAL_USE_BASIC_VIEWER) || defined(CGAL_EXT_DOXYGEN_RUNNING)

/// \ingroup PkgMobiusMeshDrawing
/// \brief A `CGAL::Basic_viewer_qt` showing the two sides of a `Mobius_mesh`
/// (`make_two_sided_scene()`): what `draw()` opens.
///
/// The viewer's keys are CGAL's (`H` lists them): `F` hides the faces, `E`
/// the edges, `S` switches to smooth shading with the scene's per-side normals.
class Mobius_mesh_viewer_qt : public CGAL::Basic_viewer_qt
{
public:
  /// Shows `scene` in a window titled `title`.
  Mobius_mesh_viewer_qt(QWidget* parent, const Two_sided_scene& scene, const char* title = "Mobius_mesh viewer")
    : CGAL::Basic_viewer_qt(parent, title, /*draw_vertices*/ false, /*draw_edges*/ true, /*draw_faces*/ true,
                            /*use_mono_color*/ false, /*inverse_normal*/ false)
  {
    add_scene(scene);
  }

  /// Shows `mesh` in a window titled `title`, with the named parameters of
  /// `make_two_sided_scene()`.
  template <class P, class NP = parameters::Default_named_parameters>
  Mobius_mesh_viewer_qt(QWidget* parent, const Mobius_mesh<P>& mesh, const char* title = "Mobius_mesh viewer",
                        const NP& np = parameters::default_values())
    : Mobius_mesh_viewer_qt(parent, make_two_sided_scene(mesh, np), title)
  {}

  /// Closes the viewer.
  ~Mobius_mesh_viewer_qt() override
  {
    // CGAL's QGLViewer listens for the end of its OpenGL context, which comes
    // in QOpenGLWidget's destructor, after QGLViewer's own: the call would
    // reach a destroyed object. It has nothing left to free by then.
    if (context())
      QObject::disconnect(context(), nullptr, this, nullptr);
    free_what_cgal_keeps();
  }

  /// Shows the faces, or hides them (`draw()`'s `nofill`; the `F` key).
  void set_draw_faces(bool faces) { m_draw_faces = faces; }

  /// Adds the faces and segments of `scene` to what is drawn, moved and
  /// scaled into a box of size 1 about the origin: OpenGL computes in float,
  /// which overflows or underflows long before the scene's double does.
  void add_scene(const Two_sided_scene& scene)
  {
    const auto& b = scene.bbox;
    const Two_sided_scene::Vector centre((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2,
                                         (b.zmin() + b.zmax()) / 2);
    const double span = (std::max)({b.x_span(), b.y_span(), b.z_span()});
    const double scale = span > 0 && std::isfinite(span) ? 1 / span : 1;
    const auto unit = [&](const Two_sided_scene::Point& p) {
      return CGAL::ORIGIN + ((p - CGAL::ORIGIN) - centre) * scale;
    };
    for (const auto& face : scene.faces) {
      if (has_no_area(scene, face))
        continue;
      face_begin(face.color);
      for (std::size_t i = face.first_corner; i < face.first_corner + face.size; ++i)
        add_point_in_face(unit(scene.corners[i]), scene.normals[i]);
      face_end();
    }
    for (const auto& segment : scene.segments)
      add_segment(unit(segment.source), unit(segment.target), segment.color);
  }

  /// Whether `face` is flat to within rounding (its corners on one line, or
  /// on one point): it has no plane for CGAL's viewer to triangulate it in,
  /// and nothing to show but its edges, which are segments of the scene.
  static bool has_no_area(const Two_sided_scene& scene, const Two_sided_scene::Face& face)
  {
    // The area vector, twice over, from the first corner (no cancellation
    // of large coordinates).
    Two_sided_scene::Vector newell = CGAL::NULL_VECTOR;
    double squared_perimeter = 0;
    const auto& origin = scene.corners[face.first_corner];
    for (std::size_t i = 0; i < face.size; ++i) {
      const auto& p = scene.corners[face.first_corner + i];
      const auto& q = scene.corners[face.first_corner + (i + 1) % face.size];
      newell = newell + CGAL::cross_product(p - origin, q - origin);
      squared_perimeter += CGAL::squared_distance(p, q);
    }
    return newell.squared_length() <= 1e-24 * squared_perimeter * squared_perimeter;
  }

  /// Looks in `direction`, with `up` up, at the whole scene once the window
  /// is shown; a zero direction keeps CGAL's default view.
  void set_view(const std::array<double, 3>& direction, const std::array<double, 3>& up)
  {
    view_direction_ = direction;
    up_vector_ = up;
  }

  /// Writes a picture of what the viewer shows to `file` (its format from
  /// its suffix) once the window has been drawn, then calls `done`.
  void take_screenshot(const std::string& file, std::function<void()> done)
  {
    screenshot_file_ = file;
    screenshot_done_ = std::move(done);
  }

private:
  // CGAL 5.5's viewer makes its shaders with `new` and adds them to its
  // programs, which do not own them, and makes its clipping plane's frame
  // with `new`; its destructor frees neither (3 KB a viewer, which the
  // leak checker reports). A later CGAL may own them: left to it.
  void free_what_cgal_keeps()
  {
#if CGAL_VERSION_NR < 1050600000
    if (context())
      makeCurrent(); // a shader is deleted in its context
    for (QOpenGLShaderProgram* program : {&rendering_program_face, &rendering_program_p_l, &rendering_program_clipping_plane}) {
      const QList<QOpenGLShader*> shaders = program->shaders();
      program->removeAllShaders();
      qDeleteAll(shaders);
    }
    if (manipulatedFrame() == m_frame_plane)
      setManipulatedFrame(nullptr);
    delete m_frame_plane;
    m_frame_plane = nullptr;
#endif
  }

protected:
  /// Sets the view and schedules the screenshot once OpenGL is ready.
  void init() override
  {
    CGAL::Basic_viewer_qt::init();
    setBackgroundColor(::QColor(::Qt::white)); // as CGAL's viewer clears, and pictures in a manual want
    const auto& d = view_direction_;
    if (d[0] != 0 || d[1] != 0 || d[2] != 0) {
      camera()->setUpVector(CGAL::qglviewer::Vec(up_vector_[0], up_vector_[1], up_vector_[2]));
      camera()->setViewDirection(CGAL::qglviewer::Vec(d[0], d[1], d[2]));
      showEntireScene();
    }
    if (!screenshot_file_.empty())
      // After the first frame, from the event loop: the snapshot draws again
      // into its own frame buffer, which needs the context init() made.
      QTimer::singleShot(0, this, [this] {
        saveSnapshot(QString::fromStdString(screenshot_file_), width(), height());
        if (screenshot_done_)
          screenshot_done_();
      });
  }

private:
  std::array<double, 3> view_direction_{{0.0, 0.0, 0.0}};
  std::array<double, 3> up_vector_{{0.0, 0.0, 1.0}};
  std::string screenshot_file_;
  std::function<void()> screenshot_done_;
};

namespace internal {

// A QApplication for the length of one drawing, unless the program has one.
// Qt aborts the program when it finds no display, so that is checked first.
class Viewer_application
{
public:
  explicit Viewer_application(const std::string& what)
  {
    if (QApplication::instance())
      return;
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") && !std::getenv("QT_QPA_PLATFORM"))
      throw Error(what + ": no display to draw on (DISPLAY is not set; xvfb-run gives a program one)");
    CGAL::Qt::init_ogl_context(4, 3);
    app_ = std::make_unique<QApplication>(argc_, argv_);
  }
  int exec() { return QApplication::exec(); }

private:
  int argc_ = 1;
  char name_[9] = "CGAL_ext";
  char* argv_[2] = {name_, nullptr};
  std::unique_ptr<QApplication> app_;
};

} // namespace internal

#endif // CGAL_USE_BASIC_VIEWER || CGAL_EXT_DOXYGEN_RUNNING

namespace internal {

// `d` divided by its largest coordinate: the camera normalises it in float,
// where a direction of 1e200 (or 1e-200) would be infinite (or zero).
inline std::array<double, 3> scaled_direction(std::array<double, 3> d, const char* what)
{
  const double largest = (std::max)({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  if (!(largest > 0) || !std::isfinite(largest))
    throw Parameter_error(std::string("save_screenshot: the ") + what + " (" + std::to_string(d[0]) + ", " +
                          std::to_string(d[1]) + ", " + std::to_string(d[2]) + ") is zero or not finite");
  for (double& x : d)
    x /= largest;
  return d;
}

template <class P, class NP>
void draw_two_sided(const Mobius_mesh<P>& mesh, const NP& np, const char* title, bool nofill)
{
#ifdef CGAL_USE_BASIC_VIEWER
  const Two_sided_scene scene = make_two_sided_scene(mesh, np);
  if (qEnvironmentVariableIsSet("CGAL_TEST_SUITE"))
    return;
  internal::Viewer_application app("draw");
  Mobius_mesh_viewer_qt viewer(nullptr, scene, title);
  viewer.set_draw_faces(!nofill);
  viewer.show();
  app.exec();
#else
  (void)mesh, (void)np, (void)title, (void)nofill;
  std::cerr << "CGAL_ext::draw: built without CGAL_USE_BASIC_VIEWER (link with CGAL::CGAL_Basic_viewer)\n";
#endif
}

} // namespace internal

/// \ingroup PkgMobiusMeshDrawing
/// \brief opens a window showing `mesh` and returns when it is closed, as
/// `CGAL::draw()` does.
///
/// Each side of the surface in its own colour (`make_two_sided_scene()`):
/// where a face's orientation points one side is blue, the other orange, and
/// the colours swap across each Möbius edge (drawn green), so a one-sided
/// surface shows both colours on one side. Borders are red, sharp edges
/// purple by their sharpness. Takes the named parameters of
/// `make_two_sided_scene()`. Does nothing but say so on `std::cerr` when
/// built without `CGAL_USE_BASIC_VIEWER`; with the environment variable
/// `CGAL_TEST_SUITE` set, builds the scene and returns without a window (as
/// `CGAL::draw()`).
/// \throws Parameter_error as `make_two_sided_scene()`, before a window opens;
/// \throws Error when there is no display to open it on.
///
/// The call shapes of CGAL's `draw()` for a `Surface_mesh` work too:
/// `draw(mesh)`, `draw(mesh, title)` and `draw(mesh, title, nofill)`.
template <class P, class NP = parameters::Default_named_parameters,
          std::enable_if_t<!std::is_convertible<const NP&, const char*>::value, int> = 0>
void draw(const Mobius_mesh<P>& mesh, const NP& np = parameters::default_values(),
          const char* title = "Mobius_mesh viewer")
{
  internal::draw_two_sided(mesh, np, title, false);
}

/// \ingroup PkgMobiusMeshDrawing
/// \brief `draw()` called as CGAL's `draw(sm, title, nofill)`: opens a window
/// titled `title` showing `mesh`; with `nofill` the faces are hidden (the
/// viewer's `F` key shows them), as in CGAL.
template <class P>
void draw(const Mobius_mesh<P>& mesh, const char* title, bool nofill = false)
{
  internal::draw_two_sided(mesh, parameters::default_values(), title, nofill);
}

/// \ingroup PkgMobiusMeshDrawing
/// \brief draws `mesh` as `draw()` does, in a window of its own for the
/// moment it takes, and writes the picture to `file` (PNG, or another format
/// Qt writes, by its suffix).
///
/// It needs a display (an X server; `xvfb-run` gives one to a program without
/// a screen) with OpenGL 4.3 or 2.1 ES. It runs an event loop of its own, so
/// a Qt program may call it from its running loop. The picture is written
/// aside and renamed into place, so a failure leaves an existing `file` as
/// it was. Takes the named parameters of `make_two_sided_scene()`.
/// \throws Parameter_error as `make_two_sided_scene()`, when the picture
/// is not between 16 and 8192 pixels wide and high, or when the view
/// direction or the up vector is zero or not finite;
/// \throws Error when there is no display;
/// \throws IO_error if `file` is a directory or its directory is missing or
/// not writable (checked before drawing), if no picture could be written to
/// `file`, or when built
/// without `CGAL_USE_BASIC_VIEWER`.
template <class P, class NP = parameters::Default_named_parameters>
void save_screenshot(const Mobius_mesh<P>& mesh, const std::string& file, const Screenshot_settings& settings = {},
                     const NP& np = parameters::default_values())
{
  const auto in_range = [](int n) { return n >= 16 && n <= 8192; };
  if (!in_range(settings.width) || !in_range(settings.height))
    throw Parameter_error("save_screenshot: a picture of " + std::to_string(settings.width) + " x " +
                          std::to_string(settings.height) + " pixels; each side must be from 16 to 8192");
  IO::internal::check_output_path(file); // before the drawing, not after it
  const auto direction = internal::scaled_direction(settings.view_direction, "view direction");
  const auto up = internal::scaled_direction(settings.up_vector, "up vector");
#ifdef CGAL_USE_BASIC_VIEWER
  const Two_sided_scene scene = make_two_sided_scene(mesh, np);
  const std::size_t dot = file.find_last_of('.');
  const std::string suffix = dot == std::string::npos || file.find('/', dot) != std::string::npos ? ".png"
                                                                                                 : file.substr(dot);
  const std::string aside = file + ".part" + suffix; // Qt picks the format by the suffix
  std::remove(aside.c_str());
  {
    internal::Viewer_application app("save_screenshot");
    QEventLoop loop;
    Mobius_mesh_viewer_qt viewer(nullptr, scene, "Mobius_mesh screenshot");
    viewer.set_view(direction, up);
    viewer.take_screenshot(aside, [&loop] { loop.quit(); });
    viewer.resize(settings.width, settings.height);
    // A window that is never drawn (no OpenGL) must not hang the caller.
    QTimer::singleShot(60000, &loop, &QEventLoop::quit);
    viewer.show();
    loop.exec(); // its own loop: a program's running loop is left as it is
  }
  if (!std::ifstream(aside).good())
    throw IO_error(file, 0, "no picture was written (is there a display with OpenGL?)");
  if (std::rename(aside.c_str(), file.c_str()) != 0) {
    std::remove(aside.c_str());
    throw IO_error(file, 0, "the picture could not be moved into place");
  }
#else
  (void)mesh, (void)np, (void)direction, (void)up;
  throw IO_error(file, 0, "save_screenshot: built without CGAL_USE_BASIC_VIEWER (link with CGAL::CGAL_Basic_viewer)");
#endif
}

} // namespace CGAL_ext

#endif // CGAL_EXT_DRAW_MOBIUS_MESH_H
