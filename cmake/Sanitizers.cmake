if(CUTCALC_SANITIZE)
  # Applied to everything we compile so that ASan sees every allocation made by our code.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()
