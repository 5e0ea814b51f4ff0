# The libraries of the browser build (scripts/build-web.sh), which compiles with Emscripten.
# Its toolchain finds packages in its own sysroot only, and the host's /usr/include must stay out
# of a WebAssembly compile. So Debian's header-only packages (Eigen, nlohmann-json, {fmt},
# fast_float) are taken through a folder of links to their own folders, and GSL is the
# WebAssembly build of scripts/build-gsl-wasm.sh, built from Debian's source of the same GSL.
set(TREBUCHET_GSL_WASM "" CACHE PATH "GSL built for WebAssembly (the prefix scripts/build-gsl-wasm.sh prints)")
if(NOT EXISTS "${TREBUCHET_GSL_WASM}/lib/libgsl.a")
  message(FATAL_ERROR "TREBUCHET_GSL_WASM='${TREBUCHET_GSL_WASM}' holds no lib/libgsl.a; run scripts/build-gsl-wasm.sh and pass the prefix it prints")
endif()
set(host_headers ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${host_headers})
foreach(link Eigen:/usr/include/eigen3/Eigen nlohmann:/usr/include/nlohmann fmt:/usr/include/fmt fast_float:/usr/include/fast_float)
  string(REPLACE ":" ";" pair ${link})
  list(GET pair 0 name)
  list(GET pair 1 target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "${target} is missing; run scripts/install-deps.sh")
  endif()
  file(CREATE_LINK ${target} ${host_headers}/${name} SYMBOLIC)
endforeach()
foreach(name Eigen3::Eigen nlohmann_json::nlohmann_json trebuchet_fast_float)
  add_library(${name} INTERFACE IMPORTED)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${host_headers})
endforeach()
add_library(fmt::fmt-header-only INTERFACE IMPORTED)
set_target_properties(fmt::fmt-header-only PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${host_headers} INTERFACE_COMPILE_DEFINITIONS FMT_HEADER_ONLY=1)
add_library(GSL::gsl STATIC IMPORTED)
set_target_properties(GSL::gsl PROPERTIES IMPORTED_LOCATION ${TREBUCHET_GSL_WASM}/lib/libgsl.a INTERFACE_INCLUDE_DIRECTORIES ${TREBUCHET_GSL_WASM}/include)
# The library reports every refusal by an exception: WebAssembly's own exceptions (Chrome 95,
# Firefox 100, Safari 15.2 on), which cost nothing until thrown; the JavaScript-based ones of
# -fexceptions made every call that may throw pass through JavaScript, a shot twice as slow.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
