#include "viewer/Viewer.h"

#include <GL/freeglut.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <ostream>

#include "image/PngFile.h"
#include "render/GlRenderer.h"

namespace tabletop {
namespace {

// The menu's entries.
enum MenuItem {
  kArrowOn, kArrowOff,
  kRotateTableAndEntities, kRotateEntitiesOnTable,
  kZoomIn, kZoomOut,
  kRotateClockwise, kRotateCounterclockwise,
  kReset, kMoveEntity,
  kPause, kSingleStep, kSlowMotionItem, kContacts, kPlayScript, kScreenshot, kQuit,
};

constexpr unsigned kFrameMilliseconds = 16;  // about 60 frames a second
constexpr double kOrbitDegreesPerPixel = 0.3;
constexpr double kZoomStep = 0.9;
constexpr double kSlowMotion = 0.25;
void* const kFont = GLUT_BITMAP_9_BY_15;
constexpr int kLineHeight = 17;  // pixels
constexpr double kEscSeconds = 1.5;  // between the two presses of Esc that quit

// The open window: the session it shows and what the mouse is doing.
class Window {
 public:
  Window(ViewerSession& session, const WindowSettings& settings)
      : session_(session), settings_(settings), width_(settings.width), height_(settings.height) {}

  void open();

  // freeglut calls these through the trampolines below.
  void display();
  void reshape(int w, int h) { width_ = w, height_ = h; }
  void key(unsigned char key, int x, int y);
  void special(int key);
  void mouse(int button, int state, int x, int y);
  void motion(int x, int y);
  void wheel(int direction);
  void menu(int item);
  void tick();

 private:
  void drawOverlay();
  void screenshot();

  ViewerSession& session_;
  WindowSettings settings_;
  int width_, height_;
  std::unique_ptr<GlRenderer> renderer_;
  GlFunctions gl_;
  void (*windowPos_)(GLint, GLint) = nullptr;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  enum class Drag { Still, Orbit, Pan } drag_ = Drag::Still;
  int dragX_ = 0, dragY_ = 0;
  bool dragged_ = false;
  bool help_ = false;
  std::chrono::steady_clock::time_point escPressed_{};
  bool screenshotDue_ = false;
  int screenshots_ = 0;
};

Window& self(void* data) { return *static_cast<Window*>(data); }

void Window::open() {
  // Multisampled (anti-aliased) where the display offers it.
  glutSetOption(GLUT_MULTISAMPLE, 4);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL | GLUT_MULTISAMPLE);
  glutInitWindowSize(width_, height_);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  const std::string title = "tabletop: " + session_.scenario().name + " (" +
                            std::string(session_.simulation().modeName()) + ")";
  glutCreateWindow(title.c_str());
  gl_ = GlFunctions::load([](const char* name) { return reinterpret_cast<void*>(glutGetProcAddress(name)); });
  windowPos_ = reinterpret_cast<void (*)(GLint, GLint)>(glutGetProcAddress("glWindowPos2i"));
  renderer_ = std::make_unique<GlRenderer>(gl_);
  gl_.Enable(GL_MULTISAMPLE);

  glutDisplayFuncUcall([](void* d) { self(d).display(); }, this);
  glutReshapeFuncUcall([](int w, int h, void* d) { self(d).reshape(w, h); }, this);
  glutKeyboardFuncUcall([](unsigned char k, int x, int y, void* d) { self(d).key(k, x, y); }, this);
  glutSpecialFuncUcall([](int k, int, int, void* d) { self(d).special(k); }, this);
  glutMouseFuncUcall([](int b, int s, int x, int y, void* d) { self(d).mouse(b, s, x, y); }, this);
  glutMotionFuncUcall([](int x, int y, void* d) { self(d).motion(x, y); }, this);
  glutMouseWheelFuncUcall([](int, int dir, int, int, void* d) { self(d).wheel(dir); }, this);

  // The report's right-button menu, then the viewer's own entries.
  const auto onMenu = [](int item, void* d) { self(d).menu(item); };
  const int pushDirection = glutCreateMenuUcall(onMenu, this);
  glutAddMenuEntry("On", kArrowOn);
  glutAddMenuEntry("Off", kArrowOff);
  const int rotationEntities = glutCreateMenuUcall(onMenu, this);
  glutAddMenuEntry("Table and Entities", kRotateTableAndEntities);
  glutAddMenuEntry("Entities on the table", kRotateEntitiesOnTable);
  const int zoom = glutCreateMenuUcall(onMenu, this);
  glutAddMenuEntry("Zoom In", kZoomIn);
  glutAddMenuEntry("Zoom Out", kZoomOut);
  const int rotation = glutCreateMenuUcall(onMenu, this);
  glutAddMenuEntry("Rotate clockwise", kRotateClockwise);
  glutAddMenuEntry("Rotate counterclockwise", kRotateCounterclockwise);
  glutCreateMenuUcall(onMenu, this);
  glutAddSubMenu("Push Direction", pushDirection);
  glutAddSubMenu("Set Rotation Entities", rotationEntities);
  glutAddSubMenu("Zoom", zoom);
  glutAddSubMenu("Rotation", rotation);
  glutAddMenuEntry("Reset", kReset);
  glutAddMenuEntry("Move entity", kMoveEntity);
  glutAddMenuEntry("Pause / resume (P)", kPause);
  glutAddMenuEntry("One step (O)", kSingleStep);
  glutAddMenuEntry("Slow motion (S)", kSlowMotionItem);
  glutAddMenuEntry("Contact points (C)", kContacts);
  glutAddMenuEntry("Play the script (Enter)", kPlayScript);
  glutAddMenuEntry("Screenshot (F12)", kScreenshot);
  glutAddMenuEntry("Quit (Q)", kQuit);
  glutAttachMenu(GLUT_RIGHT_BUTTON);

  glutTimerFuncUcall(kFrameMilliseconds, [](int, void* d) { self(d).tick(); }, 0, this);
}

void Window::tick() {
  const auto now = std::chrono::steady_clock::now();
  session_.advance(std::chrono::duration<double>(now - last_).count());
  last_ = now;
  glutPostRedisplay();
  glutTimerFuncUcall(kFrameMilliseconds, [](int, void* d) { self(d).tick(); }, 0, this);
}

void Window::display() {
  renderer_->draw(session_.drawList(), session_.camera(), width_, height_);
  if (screenshotDue_) {
    screenshotDue_ = false;
    screenshot();  // the scene alone, before the overlay
  }
  drawOverlay();
  glutSwapBuffers();
}

void Window::drawOverlay() {
  std::vector<std::string> lines = session_.overlay(static_cast<std::size_t>(std::max(4, (height_ - 10) / kLineHeight)));
  if (help_) {
    lines.emplace_back("");
    for (const std::string& h : ViewerSession::help()) lines.push_back(h);
  }
  // A dark band behind the text keeps it legible on any background.
  std::size_t longest = 0;
  for (const std::string& l : lines) longest = std::max(longest, l.size());
  const double right = 12.0 + 9.0 * static_cast<double>(longest);
  const double bottom = 10.0 + kLineHeight * static_cast<double>(lines.size());
  gl_.Disable(GL_LIGHTING);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.MatrixMode(GL_PROJECTION);
  Mat4 ortho;  // pixels, origin top left
  ortho.at(0, 0) = 2.0 / width_, ortho.at(0, 3) = -1.0;
  ortho.at(1, 1) = -2.0 / height_, ortho.at(1, 3) = 1.0;
  gl_.LoadMatrixd(ortho.m.data());
  gl_.MatrixMode(GL_MODELVIEW);
  gl_.LoadIdentity();
  gl_.Enable(GL_BLEND);
  gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl_.Color4ub(0, 0, 0, 140);
  gl_.Begin(GL_QUADS);
  gl_.Vertex3d(0, 0, 0);
  gl_.Vertex3d(0, bottom, 0);
  gl_.Vertex3d(right, bottom, 0);
  gl_.Vertex3d(right, 0, 0);
  gl_.End();
  gl_.Disable(GL_BLEND);
  gl_.Color4ub(255, 255, 255, 255);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (windowPos_) windowPos_(6, height_ - kLineHeight * static_cast<int>(i + 1));
    glutBitmapString(kFont, reinterpret_cast<const unsigned char*>(lines[i].c_str()));
  }
  gl_.Enable(GL_DEPTH_TEST);
  gl_.Enable(GL_LIGHTING);
}

void Window::screenshot() {
  namespace fs = std::filesystem;
  fs::path path;
  do {
    path = fs::path(settings_.screenshotDir) /
           ("tabletop_" + session_.scenario().name + "_" + std::to_string(++screenshots_) + ".png");
  } while (fs::exists(path));
  try {
    writePng(renderer_->readPixels(width_, height_), path.string());
    session_.showMessage("screenshot " + path.string());
  } catch (const std::runtime_error& e) {
    session_.showMessage(std::string("no screenshot: ") + e.what());
  }
}

void Window::key(unsigned char key, int, int) {
  switch (key) {
    case ' ': session_.cycleArrow(); break;
    case 'g': case 'G': session_.pushArrowed(); break;
    case '+': case '=': session_.rotate(+1); break;
    case '-': case '_': session_.rotate(-1); break;
    case 'a': case 'A': session_.setArrowVisible(!session_.arrowVisible()); break;
    case 'c': case 'C': session_.toggleContacts(); break;
    case 'p': case 'P': session_.togglePause(); break;
    case 'o': case 'O': session_.singleStep(); break;
    case 's': case 'S': session_.setSpeed(session_.speed() == 1.0 ? kSlowMotion : 1.0); break;
    case '[': session_.setSpeed(0.5 * session_.speed()); break;
    case ']': session_.setSpeed(2.0 * session_.speed()); break;
    case 'r': case 'R': session_.reset(false); break;
    case '\r': case '\n': session_.reset(true); break;
    case 'z': case 'Z': session_.camera().zoom(kZoomStep); break;
    case 'x': case 'X': session_.camera().zoom(1.0 / kZoomStep); break;
    case 'h': case 'H': help_ = !help_; break;
    case 'f': case 'F': session_.fitCamera(double(width_) / height_); break;
    case 't': case 'T': session_.toggleFollow(); break;
    case '\t': session_.nextEntity(); break;
    case 'i': case 'I': session_.toggleOverlay(); break;
    case 'l': case 'L': session_.toggleEntityList(); break;
    case 'q': case 'Q': glutLeaveMainLoop(); break;
    case 27: {
      // freeglut passes on the Esc that closes the right-button menu, so
      // Esc quits only when pressed twice within kEscSeconds.
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - escPressed_).count() < kEscSeconds) {
        glutLeaveMainLoop();
      } else {
        escPressed_ = now;
        session_.showMessage("Esc again quits (Q quits at once)");
      }
      break;
    }
    default: break;
  }
  glutPostRedisplay();
}

void Window::special(int key) {
  if (key == GLUT_KEY_F12) screenshotDue_ = true;
  glutPostRedisplay();
}

void Window::mouse(int button, int state, int x, int y) {
  if (state == GLUT_UP) {
    // A left click that did not drag picks the entity under it.
    if (button == GLUT_LEFT_BUTTON && !dragged_) session_.pick(x, y, width_, height_);
    drag_ = Drag::Still;
    glutPostRedisplay();
    return;
  }
  if (button == 3 || button == 4) return;  // wheel, seen by wheel()
  dragX_ = x, dragY_ = y;
  dragged_ = false;
  const bool shift = glutGetModifiers() & GLUT_ACTIVE_SHIFT;
  if (button == GLUT_LEFT_BUTTON) drag_ = shift ? Drag::Pan : Drag::Orbit;
  if (button == GLUT_MIDDLE_BUTTON) drag_ = Drag::Pan;
}

void Window::motion(int x, int y) {
  const int dx = x - dragX_, dy = y - dragY_;
  dragX_ = x, dragY_ = y;
  dragged_ = dragged_ || dx != 0 || dy != 0;
  if (drag_ == Drag::Orbit) session_.camera().orbit(-kOrbitDegreesPerPixel * dx, kOrbitDegreesPerPixel * dy);
  if (drag_ == Drag::Pan) session_.camera().pan(-double(dx) / height_, double(dy) / height_);
  glutPostRedisplay();
}

void Window::wheel(int direction) {
  session_.camera().zoom(direction > 0 ? kZoomStep : 1.0 / kZoomStep);
  glutPostRedisplay();
}

void Window::menu(int item) {
  switch (item) {
    case kArrowOn: session_.setArrowVisible(true); break;
    case kArrowOff: session_.setArrowVisible(false); break;
    case kRotateTableAndEntities: session_.setRotationTarget(RotationTarget::TableAndEntities); break;
    case kRotateEntitiesOnTable: session_.setRotationTarget(RotationTarget::EntitiesOnTable); break;
    case kZoomIn: session_.camera().zoom(kZoomStep); break;
    case kZoomOut: session_.camera().zoom(1.0 / kZoomStep); break;
    case kRotateClockwise: session_.rotate(-1); break;
    case kRotateCounterclockwise: session_.rotate(+1); break;
    case kReset: session_.reset(false); break;
    case kMoveEntity: session_.pushArrowed(); break;
    case kPause: session_.togglePause(); break;
    case kSingleStep: session_.singleStep(); break;
    case kSlowMotionItem: session_.setSpeed(session_.speed() == 1.0 ? kSlowMotion : 1.0); break;
    case kContacts: session_.toggleContacts(); break;
    case kPlayScript: session_.reset(true); break;
    case kScreenshot: screenshotDue_ = true; break;
    case kQuit: glutLeaveMainLoop(); break;
    default: break;
  }
  glutPostRedisplay();
}

}  // namespace

std::string displayProblem() {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) return "DISPLAY is not set";
  Display* display = XOpenDisplay(nullptr);
  if (!display) return std::string("cannot open display '") + name + "'";
  XCloseDisplay(display);
  return {};
}

std::string noDisplayMessage(const std::string& problem) {
  return "tabletop view: needs a display (" + problem +
         "); to make pictures without one use: tabletop render SCENARIO --out-dir DIR";
}

int runViewer(ViewerSession& session, const WindowSettings& settings, std::ostream& err) {
  const std::string problem = displayProblem();
  if (!problem.empty()) {
    err << noDisplayMessage(problem) << "\n";
    return 1;
  }
  int argc = 1;
  char name[] = "tabletop";
  char* argv[] = {name, nullptr};
  glutInit(&argc, argv);
  Window window(session, settings);
  window.open();
  glutMainLoop();
  return 0;
}

}  // namespace tabletop
