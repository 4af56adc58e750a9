# Project-wide warning and sanitizer flags, applied through one interface target
# so third-party headers (Ipopt, Eigen) stay quiet as system includes.
add_library(gaitopt_options INTERFACE)
target_compile_options(gaitopt_options INTERFACE -Wall -Wextra -Wpedantic)
if(GAITOPT_SANITIZE)
  target_compile_options(gaitopt_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
    # UBSan's null and alignment checks guard every reference Eigen binds: they cost 30 % of the
    # sanitizer build's compile time. ASan reports a null dereference itself (SEGV with its
    # stack), and a misaligned Eigen packet load faults on x86-64; UBSan keeps the arithmetic,
    # bounds, enum, bool, return and shift checks.
    -fno-sanitize=null,alignment)
  target_link_options(gaitopt_options INTERFACE -fsanitize=address,undefined)
endif()
if(GAITOPT_FUZZ)
  # Coverage feedback for libFuzzer in every gaitopt library; fuzz/ links the fuzzer driver.
  target_compile_options(gaitopt_options INTERFACE
    -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  target_link_options(gaitopt_options INTERFACE -fsanitize=address,undefined)
endif()
