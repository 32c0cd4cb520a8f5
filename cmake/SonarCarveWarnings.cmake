# sonarcarve_set_warnings(target): the project's warning set, errors when SONARCARVE_WERROR is on.
function(sonarcarve_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual
    -Wnull-dereference -Wimplicit-fallthrough
    # GCC 12 reports false -Wrestrict on std::string concatenation at -O3 (GCC bug 105329).
    $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)
  if(SONARCARVE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
