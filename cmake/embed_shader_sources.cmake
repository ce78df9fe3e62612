# Writes OUTPUT: a C++ file defining lancer::gpu::embedded_shader_files(), every file under
# SHADER_DIR (relative name -> text), so the run-time compiler can build the tracer without the
# source tree. Run with: cmake -DSHADER_DIR=... -DOUTPUT=... -P embed_shader_sources.cmake
file(GLOB_RECURSE files RELATIVE ${SHADER_DIR} ${SHADER_DIR}/*.comp ${SHADER_DIR}/*.glsl ${SHADER_DIR}/*.h)
list(SORT files)
set(body "")
foreach(name IN LISTS files)
  file(READ ${SHADER_DIR}/${name} text)
  # Raw string literals are limited in length by some compilers; split every 8000 characters.
  string(LENGTH "${text}" length)
  set(pieces "")
  set(offset 0)
  while(offset LESS length)
    string(SUBSTRING "${text}" ${offset} 8000 piece)
    string(APPEND pieces "R\"lancer_src(${piece})lancer_src\"\n")
    math(EXPR offset "${offset} + 8000")
  endwhile()
  if(pieces STREQUAL "")
    set(pieces "\"\"")
  endif()
  string(APPEND body "        {\"${name}\", std::string(${pieces})},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from shaders/ by cmake/embed_shader_sources.cmake. Do not edit.
#include <map>
#include <string>

namespace lancer::gpu {

const std::map<std::string, std::string>& embedded_shader_files() {
    static const std::map<std::string, std::string> files = {
${body}    };
    return files;
}

}  // namespace lancer::gpu
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
