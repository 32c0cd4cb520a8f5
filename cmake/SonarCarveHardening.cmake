# Debian's hardening flags (dpkg-buildflags with hardening=+all), since the programs read vendor
# logs from anywhere: fortified libc calls, a stack protector, and a read-only GOT bound at
# start-up (relro is the linker's default). Off for sanitizer and fuzzing builds, whose
# instrumentation replaces these checks; fortification needs an optimised build.
option(SONARCARVE_HARDENING "Build with Debian's hardening flags" ON)
if(SONARCARVE_HARDENING AND NOT SONARCARVE_FUZZ AND NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  add_compile_options(-fstack-protector-strong
                      $<$<NOT:$<CONFIG:Debug>>:-D_FORTIFY_SOURCE=2>)
  add_link_options(LINKER:-z,relro LINKER:-z,now)
endif()
