# The prover's own mistakes, planted one at a time: each an edit of one source of the proving (the C++
# reader, Gappa's runs, verdict and cache, the Gappa scripts), built into a billiards-derive of its own,
# which must refuse — exit status 1, stderr matching what must catch it, every model's audit written and
# no header — and never crash. Included from tests/derive/CMakeLists.txt.
#
# billiards_prover_mutant(NAME SOURCE EXPECT FROM TO [FROM TO …]): SOURCE (under derive/) with the text of
# each variable FROM, which must occur exactly once, replaced by the text of the variable TO (variables, as
# the texts hold semicolons); EXPECT a regular expression stderr must match.
function(billiards_prover_mutant name source expect)
  set(path ${PROJECT_SOURCE_DIR}/derive/${source})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
  file(READ ${path} text)
  set(edits ${ARGN})
  while(edits)
    list(POP_FRONT edits from_name to_name)
    set(from "${${from_name}}")
    set(to "${${to_name}}")
    string(LENGTH "${text}" before)
    string(LENGTH "${from}" length)
    string(REPLACE "${from}" "" without "${text}")
    string(LENGTH "${without}" after)
    math(EXPR occurrences "(${before} - ${after}) / ${length}")
    if(NOT occurrences EQUAL 1)
      message(FATAL_ERROR "prover mutant ${name}: derive/${source} holds `${from}` ${occurrences} times, "
                          "expected once: update tests/derive/CMakeLists.txt to the source")
    endif()
    string(REPLACE "${from}" "${to}" text "${text}")
  endwhile()
  get_filename_component(file ${source} NAME)
  set(mutated ${CMAKE_CURRENT_BINARY_DIR}/prover_mutants/${name}/${file})
  file(WRITE ${mutated}.new "${text}")
  configure_file(${mutated}.new ${mutated} COPYONLY)

  set(others "")
  foreach(part IN LISTS billiards_prover_sources)
    get_filename_component(stem ${part} NAME_WE)
    if(NOT part STREQUAL source)
      list(APPEND others billiards_prover_${stem})
    endif()
  endforeach()
  set(target billiards-derive-prover-${name})
  add_executable(${target} ${PROJECT_SOURCE_DIR}/derive/main.cpp ${mutated})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/derive)
  target_compile_features(${target} PRIVATE cxx_std_20)
  target_link_libraries(${target} PRIVATE billiards_derivation_layers ${others} billiards_models PkgConfig::GINAC
                                          nlohmann_json::nlohmann_json CLI11::CLI11 billiards_support billiards_warnings)
  add_test(NAME derive/mutations/prover/${name}
           COMMAND ${CMAKE_COMMAND} -D DERIVE=$<TARGET_FILE:${target}> -D WORK=${CMAKE_CURRENT_BINARY_DIR}/scratch/prover/${name}
                   -D "EXPECT=${expect}" -P ${CMAKE_CURRENT_SOURCE_DIR}/prover_mutation.cmake)
endfunction()

# Gappa's verdict taken from its printing Results:, which it prints beside unsatisfied properties too.
set(from1 [[  return status == 0 && output.find("not satisfied") == std::string::npos &&
         output.find("Error") == std::string::npos;]])
set(to1 [[  return status <= 1 && output.find("Results:") != std::string::npos;]])
billiards_prover_mutant(verdict_from_results prove/gappa.cpp
  "PROVER CANARY FAILED gappa.refuses_a_false_property"
  from1 to1)
# The float scripts rounded as double.
set(from1 [[if (digits == 24 && min_exponent == -125) return "float<ieee_32, ne>";]])
set(to1 [[if (digits == 24 && min_exponent == -125) return "float<ieee_64, ne>";]])
billiards_prover_mutant(float_rounded_as_double prove/gappa.cpp
  "PROVER CANARY FAILED precision.float_rounds_as_float"
  from1 to1)
# The proof cache's key and its byte-for-byte check both without the script's first line, the @rnd line.
set(from1 [[std::filesystem::path ProofCache::path(const std::string& script) const {
]])
set(to1 [[std::filesystem::path ProofCache::path(const std::string& whole) const {
  const std::string script = whole.substr(whole.find('\n') + 1);
]])
set(from2 [[std::string ProofCache::entry(const std::string& script, int status, const std::string& output) const {
]])
set(to2 [[std::string ProofCache::entry(const std::string& whole, int status, const std::string& output) const {
  const std::string script = whole.substr(whole.find('\n') + 1);
]])
billiards_prover_mutant(cache_key_without_rounding prove/gappa.cpp
  "PROVER CANARY FAILED cache.one_line_apart_misses"
  from1 to1 from2 to2)
# The named constants' float values written into the double scripts: the double plain forms proven over
# masses up to 2^61 while the printed guard admits 2^509.
set(from1 [[value_in(bound, format_)]])
set(to1 [[value_in(bound, emitted_formats().front())]])
billiards_prover_mutant(float_constants_in_double_scripts prove/rounding.cpp
  "KERNEL NOT PROVEN plain_elastic_normal_velocity_change .*its double script states m1 in \\[2\\^-61, 2\\^61\\] where the printed guard admits m1 in \\[2\\^-509, 2\\^509\\]"
  from1 to1)
# The overflow goal twice the largest finite number.
set(from1 [[std::to_string(format.max_exponent - format.digits);]])
set(to1 [[std::to_string(format.max_exponent - format.digits + 1);]])
billiards_prover_mutant(overflow_bound_doubled prove/rounding.cpp
  "PROVER CANARY FAILED range.float_one_ulp_wider_is_refused"
  from1 to1)
# `/` a precedence level of its own, tighter than `*`: a * b / c read as a * (b / c).
set(from1 [[{"+", "-"}, {"*", "/"}};]])
set(to1 [[{"+", "-"}, {"*"}, {"/"}};]])
set(from2 [[if (level > 7) return unary();]])
set(to2 [[if (level > 8) return unary();]])
billiards_prover_mutant(reader_division_above_multiplication prove/cpp_reader.cpp
  "PROVER CANARY FAILED reader.keeps_the_grouping"
  from1 to1 from2 to2)
# Unary minus dropped by the reader.
set(from1 [[    if (peek().kind == Token::Kind::punctuation && (peek().text == "-" || peek().text == "!")) {]])
set(to1 [[    if (peek().kind == Token::Kind::punctuation && peek().text == "-") {
      ++at_;
      return unary();
    }
    if (peek().kind == Token::Kind::punctuation && peek().text == "!") {]])
billiards_prover_mutant(reader_drops_unary_minus prove/cpp_reader.cpp
  "PROVER CANARY FAILED reader.keeps_the_grouping"
  from1 to1)
