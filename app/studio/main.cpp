// fieldlines-studio: window, main loop and command line. All state lives in StudioController
// (gui/model); all drawing in fieldlines::gui. One loop draws every frame, the video import too.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "gui/model/bench_scene.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/synth/demo.hpp"
#include "fieldlines/detect/error.hpp"
#include "gui/model/frame_stats.hpp"
#include "gui/model/open_project.hpp"
#include "gui/model/recent_projects.hpp"
#include "gui/model/video_frames.hpp"
#include "gui/model/studio_args.hpp"
#include "gui/model/studio_controller.hpp"
#include "app/studio/gl_texture.hpp"
#include "app/studio/key_input.hpp"
#include "gui/model/ui_state.hpp"
#include "gui/panels/studio_window.hpp"

namespace {

using namespace fieldlines;

void on_glfw_error(int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); }

// GLFW + ImGui lifetime (RAII so every exit path tears down in order).
class Window {
 public:
  Window(int width, int height, bool vsync) {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) throw Error("cannot initialise GLFW (is a display available? try xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    window_ = glfwCreateWindow(width, height, "fieldlines studio", nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw Error("cannot create a 1280x800-class OpenGL 3.3 window");
    }
    glfwSetWindowPos(window_, 0, 0);  // a known place on screen (tests drive it with xdotool)
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(vsync ? 1 : 0);
    // Key presses reach this window's own queue (no global); installed before the ImGui backend,
    // which chains to it.
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
      if (action == GLFW_PRESS || action == GLFW_REPEAT) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->keys_.push_back({key, mods, action == GLFW_REPEAT});
      }
    });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // layout is fixed; never write imgui.ini into the cwd
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330");
  }
  ~Window() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
  GLFWwindow* get() const { return window_; }
  // Key presses since the last frame (UI thread only); the frame consumes and clears them.
  std::vector<app::KeyPress>& keys() { return keys_; }

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<app::KeyPress> keys_;
};

// Writes the state an automated test needs to drive the window (where the image is on screen,
// what is hovered, how many saves happened) whenever it changes. Atomic, so a reader never sees
// half a file.
class StateWriter {
 public:
  explicit StateWriter(std::string path) : path_(std::move(path)) {}
  void update(const studio::StudioController& c, const studio::UiState& ui) {
    if (path_.empty()) return;
    const auto& view = ui.image_view.view;
    nlohmann::json layers = nlohmann::json::array();  // the feature layers drawn, by name
    for (const studio::FeatureLayer l : studio::kFeatureLayers)
      if (ui.image_view.settings.features.on(l)) layers.push_back(studio::feature_layer_name(l));
    const FieldFeatures& f = c.field_features();
    const nlohmann::json state{{"scale", view.scale()},
                               {"offset", {view.offset().x, view.offset().y}},
                               {"image", c.current()},
                               {"hovered", c.hovered() ? static_cast<long>(*c.hovered()) : -1L},
                               {"save_count", c.save_count()},
                               {"panel", studio::panel_name(ui.shown_panel)},
                               {"training", c.training().running()},
                               {"trained", c.training().outcome().has_value()},
                               {"detection", c.detection_report().summary()},
                               {"detecting", c.detection().running()},
                               {"to_review", c.to_review()},
                               {"auto_training", c.auto_train_busy()},
                               {"image_error", c.image_error()},
                               {"text_input", ImGui::GetIO().WantTextInput},
                               {"feature_layers", layers},
                               {"features", {{"stripes", f.markings.size()},
                                             {"intersections", f.intersections.size()},
                                             {"ellipses", f.ellipses.size()},
                                             {"boundary_points", f.field_boundary.points.size()}}}};
    std::string text = state.dump();
    if (text == last_) return;
    write_file_atomically(path_, text + "\n");
    last_ = std::move(text);
  }

 private:
  std::string path_;
  std::string last_;
};

// The project to open, resolved before any window exists, so that a missing path or a damaged
// project file is a plain message on stderr and exit 2, not a window that closes again. A video
// is only located here: its frames are extracted with a progress bar once the window is up.
struct Startup {
  studio::OpenedProject opened;
  std::filesystem::path video;  // non-empty: extract its frames, then open that folder
  bool autosave = true;
};

Startup resolve_startup(const studio::StudioArgs& args, const std::vector<std::string>& recent) {
  Startup start;
  if (args.bench_frames > 0 && args.input.empty()) {
    const auto folder = std::filesystem::temp_directory_path() / ("fieldlines-bench-" + std::to_string(::getpid()));
    start.opened.project = studio::write_bench_scene(folder);
    start.opened.file = folder / "bench-project.json";
    start.autosave = false;
    return start;
  }
  std::string input = args.input;
  if (args.last) {
    // The most recent project that still exists.
    for (const auto& r : recent) {
      if (std::filesystem::exists(r)) {
        input = r;
        break;
      }
    }
    if (input.empty()) throw Error("--last: no recent project (open a project or folder once first)");
  }
  // The built-in demo project (core, shared with `fieldlines synth --demo`): 30 synthetic frames
  // over every lighting condition, some pre-labelled, generated on first use.
  if (input.empty()) input = ensure_demo().string();
  if (studio::has_video_extension(input) && std::filesystem::is_regular_file(input)) {
    start.video = input;
  } else {
    start.opened = studio::open_project(input);
  }
  start.autosave = args.bench_frames == 0;
  return start;
}

int run(const studio::StudioArgs& args) {
  const bool bench = args.bench_frames > 0;
  const auto recent_file = studio::default_recent_file();
  std::vector<std::string> recent = bench ? std::vector<std::string>{} : studio::load_recent(recent_file);
  Startup start = resolve_startup(args, recent);
  studio::ControllerOptions options;
  // A bad camera file stops the studio before its window opens (main() prints why).
  if (!args.camera_file.empty()) options.camera = load_camera_file(args.camera_file);
  Window window(args.window_width, args.window_height, !bench);
  options.autosave = start.autosave;
  options.auto_train = args.auto_train;
  options.background_save = true;
  studio::FrameStats frame_stats(bench ? static_cast<std::size_t>(args.bench_frames) : 240);
  studio::UiState ui;
  app::GlTexture texture;  // the canvas's picture (ui.image_view.picture_to_upload)
  ui.frame_stats = &frame_stats;
  ui.recent_projects = recent;
  std::vector<app::KeyPress>& keys = window.keys();

  // Behind a pointer so that opening a recent project can replace the whole session; empty while
  // a video's frames are still being extracted (`import`), which the same loop shows.
  std::unique_ptr<studio::StudioController> session;
  std::unique_ptr<studio::VideoImport> import;
  const auto open_session = [&](studio::OpenedProject opened) {
    if (session) {
      session->flush();
      if (const std::string failed = session->finish_saves(); !failed.empty())
        std::fprintf(stderr, "fieldlines-studio: the last save of %s failed: %s\n", session->project_file().c_str(),
                     failed.c_str());
    }
    session.reset();  // joins its jobs before the new session starts
    session = std::make_unique<studio::StudioController>(std::move(opened.project), opened.file, options);
    if (opened.needs_detection) session->detect_all(true);
    if (!bench) {
      studio::remember(recent, std::filesystem::absolute(opened.file).string());
      studio::save_recent(recent_file, recent);
      ui.recent_projects = recent;
    }
  };
  if (start.video.empty()) {
    open_session(std::move(start.opened));
    if (bench && args.input.empty()) {  // the synthetic scene: its features, every layer drawn
      session->set_field_features(0, studio::bench_scene_features());
      if (args.bench_features) ui.image_view.settings.features = studio::FeatureLayers::all();
    }
  } else {
    import = std::make_unique<studio::VideoImport>(start.video, args.video_every);
  }

  StateWriter state_writer(args.state_file);
  double last = glfwGetTime();  // end of the previous frame
  int frames = 0;
  int busy_frames = 0;  // keep rendering a few frames after any input so ImGui settles
  while (!glfwWindowShouldClose(window.get()) && !ui.quit_requested) {
    const bool working = import || session->training().running() || session->detection().running() ||
                         session->camera_fit().running();
    if (bench || working || busy_frames > 0) {
      glfwPollEvents();
    } else {
      glfwWaitEventsTimeout(0.1);  // idle: no need to spin the CPU
    }
    // Frame time = the work of one frame (events to swap), not the idle wait before it.
    const double frame_start = glfwGetTime();
    busy_frames = std::max(0, busy_frames - 1);
    if (!keys.empty() || ImGui::GetIO().MouseDelta.x != 0 || ImGui::GetIO().MouseDelta.y != 0) busy_frames = 4;
    for (bool down : ImGui::GetIO().MouseDown) busy_frames = down ? 4 : busy_frames;

    if (import) {
      import->poll();  // a failed extraction throws: a message and exit 2, as for a bad project
      if (import->done()) {
        open_session(studio::open_project(import->folder()));
        import.reset();
      }
    }
    if (session) session->poll(glfwGetTime());
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    app::route_tab_key();
    ImGui::NewFrame();
    if (session) {
      const app::MissedKeyReplay missed_keys(keys);  // text fields get the quick taps ImGui 1.86 loses
      app::run_shortcuts(keys, *session, ui);
      if (const cv::Mat* picture = ui.image_view.picture_to_upload(*session)) {
        ui.image_view.fit_requested |= picture->cols != texture.width() || picture->rows != texture.height();
        texture.upload(*picture);
      }
      gui::draw_studio(*session, ui, {texture.id(), texture.width(), texture.height()});
    } else {
      gui::draw_video_import(*import, ui);
    }
    keys.clear();
    ImGui::Render();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window.get(), &width, &height);
    glViewport(0, 0, width, height);
    const ImVec4 kClear{0.1f, 0.1f, 0.11f, 1};  // behind the video import window
    const ImVec4 clear = session ? gui::studio_backdrop(kClear) : kClear;
    glClearColor(clear.x, clear.y, clear.z, clear.w);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window.get());
    if (session) state_writer.update(*session, ui);
    if (session && !ui.open_request.empty()) {
      const std::string request = std::exchange(ui.open_request, {});
      try {
        auto opened = studio::open_project(request);
        const std::string file = opened.file.string();
        open_session(std::move(opened));
        ui.image_view.reupload();
        ui.image_view.fit_requested = true;
        ui.status_message = "opened " + file;
      } catch (const std::exception& e) {
        ui.status_message = e.what();
      }
    }

    frame_stats.add(glfwGetTime() - (bench ? last : frame_start));
    last = glfwGetTime();  // bench: frame-to-frame, so nothing between frames goes unmeasured
    ++frames;
    if (bench && frames >= args.bench_frames) break;
  }
  // Closed before the frames were ready: ~VideoImport stops it and removes the partial folder.
  if (import) throw Error("cancelled while reading " + import->video().string());
  session->flush();  // threshold edits of the last half second
  if (const std::string failed = session->finish_saves(); !failed.empty()) {
    std::fprintf(stderr, "fieldlines-studio: the last save of %s failed: %s\n", session->project_file().c_str(),
                 failed.c_str());
    return 1;
  }
  if (bench) {
    std::printf("bench: %d frames at %dx%d, %zu segments, median frame time %.3f ms\n", frames, args.window_width,
                args.window_height, session->segments().size(), frame_stats.median_ms());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto args = fieldlines::studio::parse_studio_args(std::vector<std::string>(argv + 1, argv + argc));
    if (args.help) {
      std::fputs(fieldlines::studio::studio_usage(), stdout);
      return 0;
    }
    if (args.version) {
      std::printf("fieldlines-studio %s\n", FIELDLINES_VERSION);
      return 0;
    }
    return run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fieldlines-studio: %s\n", e.what());
    return 2;
  }
}
