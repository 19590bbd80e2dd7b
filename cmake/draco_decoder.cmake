# Draco's decoder without its glTF transcoder, as a static archive.
#
# Debian's libdraco carries a copy of tinygltf of its own (an older one,
# inside its glTF transcoder: tiny_gltf_utils.cc and its neighbours) and
# exports its symbols. Linked in, whichever library the linker met first
# answered the project's tinygltf calls: in the fuzz build draco's copy
# did, and reading any .gltf freed memory it had not allocated. The
# decoder needs none of the transcoder, so the archive is copied without
# the members that hold or use that tinygltf, and the project's tinygltf
# calls can only reach libtinygltf.
#   cmake -DAR=ar -DIN=libdraco.a -DOUT=libdraco_decoder.a -DWORK=dir -P draco_decoder.cmake
execute_process(COMMAND "${AR}" t "${IN}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "draco_decoder: cannot list ${IN}")
endif()
string(REPLACE "\n" ";" members "${listing}")
set(keep)
foreach(member IN LISTS members)
  if(member AND NOT member MATCHES "gltf")
    list(APPEND keep "${member}")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${AR}" x "${IN}" ${keep} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "draco_decoder: cannot extract from ${IN}")
endif()
file(REMOVE "${OUT}")
execute_process(COMMAND "${AR}" qcs "${OUT}" ${keep} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "draco_decoder: cannot write ${OUT}")
endif()
file(REMOVE_RECURSE "${WORK}")
