# Writes a C++ source holding the text of every species preset (resources/presets/*.json), so the core
# (and kerf-cli without the GUI) has the presets built in. Run by core/CMakeLists.txt:
#   cmake -DOUT=<file.cpp> -DFILES=<a|b|c> -P embed_presets.cmake
string(REPLACE "|" ";" files "${FILES}")
set(text "// Generated from resources/presets/*.json by core/params/embed_presets.cmake; do not edit.\n")
string(APPEND text "#include \"params/builtin_presets.hpp\"\n\nnamespace kerf {\n\n")
string(APPEND text "const std::vector<PresetText>& builtInPresetTexts() {\n  static const std::vector<PresetText> texts = {\n")
foreach(file IN LISTS files)
  file(READ "${file}" content)
  get_filename_component(name "${file}" NAME)
  string(APPEND text "      {\"${name}\", R\"kerfjson(${content})kerfjson\"},\n")
endforeach()
string(APPEND text "  };\n  return texts;\n}\n\n}  // namespace kerf\n")
file(WRITE "${OUT}.new" "${text}")
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.new")
