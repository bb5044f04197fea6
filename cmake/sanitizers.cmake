# MINK_SANITIZE builds every mink target with AddressSanitizer and UndefinedBehaviorSanitizer;
# undefined behaviour aborts instead of printing and going on, so CTest sees it.
if(MINK_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
