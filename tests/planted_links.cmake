# Shared by the tests that a program never writes through a link planted at the file it writes
# (include() it): plant_links() makes a file `victim` holding "precious" and links to it at the given
# paths; expect_links_replaced() then fails unless the victim is untouched, none of the paths is still
# a link (each was replaced by the program's own file) and no temporary file (.NAME.tmp-*, the pattern
# of support/billiards_support/atomic_file.hpp and tools/atomic_write.py) is left in their folders.

function(plant_links victim)
  file(WRITE ${victim} "precious\n")
  foreach(path IN LISTS ARGN)
    file(CREATE_LINK ${victim} ${path} SYMBOLIC)
  endforeach()
endfunction()

function(expect_links_replaced victim)
  file(READ ${victim} contents)
  if(NOT contents STREQUAL "precious\n")
    message(FATAL_ERROR "a link's target was overwritten")
  endif()
  foreach(path IN LISTS ARGN)
    if(IS_SYMLINK ${path})
      message(FATAL_ERROR "${path} is still a link: the program wrote through it")
    endif()
    get_filename_component(folder ${path} DIRECTORY)
    file(GLOB leftovers ${folder}/.*.tmp-*)
    if(leftovers)
      message(FATAL_ERROR "temporary files left behind: ${leftovers}")
    endif()
  endforeach()
endfunction()
