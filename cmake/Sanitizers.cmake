if(CUTCALC_SANITIZE)
  # Applied to everything we compile so that ASan sees every allocation made by our code.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  # Line tables are all a sanitizer report needs (file:line in every frame); full debug info (-g)
  # made each test file ~15 % slower to compile and its object a third larger. Comes after the
  # build type's -g, so it wins.
  add_compile_options(-g1)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

option(CUTCALC_SANITIZE_THREAD "Build with ThreadSanitizer (the tsan preset)" OFF)
if(CUTCALC_SANITIZE_THREAD)
  if(CUTCALC_SANITIZE)
    message(FATAL_ERROR "ThreadSanitizer cannot be combined with AddressSanitizer")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
