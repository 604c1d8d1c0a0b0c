# Precompiled headers for the programs' libraries with many translation units: OpenCV core and
# nlohmann-json come in through nearly every fieldlines header and cost most of each file's
# compile time. The robot's library (fieldlines::detect, with its per-file ISA flags) keeps none.
# FIELDLINES_PCH=OFF builds without, which also checks that every file includes what it uses.

set(FIELDLINES_PCH_HEADERS
  <opencv2/core.hpp> <nlohmann/json.hpp>
  <algorithm> <filesystem> <functional> <map> <memory> <optional> <string> <vector>)

function(fieldlines_precompile target)
  if(FIELDLINES_PCH AND TARGET ${target})
    target_precompile_headers(${target} PRIVATE ${FIELDLINES_PCH_HEADERS} ${ARGN})
  endif()
endfunction()

fieldlines_precompile(fieldlines_data)
fieldlines_precompile(fieldlines_train)
fieldlines_precompile(fieldlines_synth)
fieldlines_precompile(fieldlines_cli)
fieldlines_precompile(fieldlines_studio_model)
fieldlines_precompile(fieldlines_gui <imgui.h>)
