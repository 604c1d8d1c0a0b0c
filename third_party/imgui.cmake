# Debian's libimgui-dev (1.86) ships no CMake config, only pkg-config `imgui`.
# Its libimgui.a already contains the GLFW and OpenGL3 backends; it also needs -lstb.
find_package(PkgConfig REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET GLOBAL imgui)
find_package(glfw3 3.3 REQUIRED GLOBAL)
find_package(OpenGL REQUIRED GLOBAL)

add_library(fieldlines_imgui INTERFACE)
add_library(fieldlines::imgui ALIAS fieldlines_imgui)
target_include_directories(fieldlines_imgui SYSTEM INTERFACE ${IMGUI_INCLUDE_DIRS} /usr/include/imgui/backends)
target_link_libraries(fieldlines_imgui INTERFACE PkgConfig::IMGUI glfw OpenGL::GL ${CMAKE_DL_LIBS})
