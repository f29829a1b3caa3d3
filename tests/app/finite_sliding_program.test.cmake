# The finite-sliding path of the program `dealvem` ('Finite strain/Enabled
# = true' with two bodies and 'Contact/Pairs'), run from a parameter file as
# a user would:
# - examples/parameters/finite-sliding-block.prm (a block pressed onto a
#   base and dragged along it by three of its element lengths, Neo-Hooke,
#   k = 2, Coulomb mu = 0.3, 12 load steps): every step converges (the JSON
#   summary says "complete" with 12 converged steps, each with its pairing
#   offset below the file's tolerance 1e-8), each wrote its VTU file and
#   appears in the .pvd, the history CSV has a line per step, and in every
#   step where all active pairs slip (measured: steps 3, 4 and 5) the
#   friction force is mu times the normal force to 1e-10 relative (the
#   Coulomb law at every pair); at least three such steps;
# - bad input: finite sliding with 'Contact/Tangential = penalty' (the
#   contact patch test of examples/step-2 with a Neo-Hooke law) and with
#   'Contact/Pairs = auto' stop with a message naming the parameter, and
#   'Contact/Maximum cutbacks = 30' (out of [0, 20]) with deal.II's message
#   naming the file, the line and the entry.
include(${TEST_DIR}/program_checks.cmake)
set(RUN_TIMEOUT 600)
set(EXAMPLES ${SOURCE_DIR}/examples/parameters)
file(REMOVE_RECURSE ${WORK_DIR}/output)

run_dealvem("finite-sliding-block.prm" TRUE "Finite strain with finite sliding: 2 bodies, 1 interface"
  ${EXAMPLES}/finite-sliding-block.prm)
set(base finite-sliding-block)
file(READ ${WORK_DIR}/output/${base}.json json)
string(JSON status GET "${json}" status)
string(JSON converged GET "${json}" converged_steps)
if(NOT status STREQUAL "complete" OR NOT converged EQUAL 12)
  message(FATAL_ERROR "FAIL finite sliding: status ${status}, ${converged} of 12 steps converged")
endif()
file(READ ${WORK_DIR}/output/${base}.pvd pvd)
file(STRINGS ${WORK_DIR}/output/${base}-history.csv csv)
list(LENGTH csv lines)
if(NOT lines EQUAL 13)
  message(FATAL_ERROR "FAIL finite sliding: ${base}-history.csv has ${lines} lines, expected a header and 12 steps")
endif()
set(all_slip 0)
foreach(s RANGE 1 12)
  string(LENGTH "00${s}" len)
  math(EXPR cut "${len} - 3")
  string(SUBSTRING "00${s}" ${cut} 3 nnn)
  if(NOT EXISTS ${WORK_DIR}/output/${base}-step-${nnn}.vtu)
    message(FATAL_ERROR "FAIL finite sliding: output/${base}-step-${nnn}.vtu was not written")
  endif()
  string(FIND "${pvd}" "file=\"${base}-step-${nnn}.vtu\"" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL finite sliding: ${base}.pvd lacks step ${s}")
  endif()
  string(JSON offset GET "${json}" steps ${s} pairing_offset)
  string(JSON active GET "${json}" steps ${s} active_pairs)
  string(JSON slipping GET "${json}" steps ${s} slipping_pairs)
  # the pairing offset is below the tolerance 1e-8 (written as a number
  # with an exponent e-09 or smaller, or 0)
  if(NOT offset MATCHES "^(0|[0-9.]+e-(09|[1-9][0-9]))$")
    message(FATAL_ERROR "FAIL finite sliding: step ${s}: pairing offset ${offset}, expected below 1e-8")
  endif()
  if(active GREATER 0 AND active EQUAL slipping)
    string(JSON ratio GET "${json}" steps ${s} interfaces 0 friction_to_normal)
    check_relative(0.3 ${ratio} 10 "finite sliding, step ${s} (all ${active} active pairs slip): friction / normal force = mu")
    math(EXPR all_slip "${all_slip} + 1")
  endif()
endforeach()
if(all_slip LESS 3)
  message(FATAL_ERROR "FAIL finite sliding: only ${all_slip} steps where every active pair slips (measured 3)")
endif()
message(STATUS "PASS finite sliding: 12 steps, each with its VTU file in ${base}.pvd and a CSV line; F_t = mu F_n in ${all_slip} steps")

# --- bad input
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm contact_prm)
file(WRITE ${WORK_DIR}/finite-sliding-penalty.prm "${contact_prm}
subsection Material
  set Law = neo-hooke
end
subsection Finite strain
  set Enabled = true
end
")
run_dealvem("finite sliding with a stick penalty" FALSE
  "Parameter 'Finite strain/Enabled' is true (finite sliding), but 'Contact/Normal' is 'unilateral' with 'Contact/Tangential = penalty'"
  ${WORK_DIR}/finite-sliding-penalty.prm)
file(READ ${EXAMPLES}/finite-sliding-block.prm block_prm)
string(REPLACE "set Pairs                = 3 : 12" "set Pairs                = auto" auto_prm "${block_prm}")
file(WRITE ${WORK_DIR}/finite-sliding-auto.prm "${auto_prm}")
run_dealvem("finite sliding with detected pairs" FALSE
  "Parameter 'Finite strain/Enabled' is true (finite sliding), but 'Contact/Pairs' has 'auto'"
  ${WORK_DIR}/finite-sliding-auto.prm)
# 'Contact/Maximum cutbacks' (FiniteSliding::Parameters::max_cutbacks) is an
# integer in [0, 20]: 30 stops the program naming the file, line and entry
string(REPLACE "subsection Contact" "subsection Contact\n  set Maximum cutbacks = 30" cutbacks_prm "${block_prm}")
file(WRITE ${WORK_DIR}/finite-sliding-cutbacks.prm "${cutbacks_prm}")
run_dealvem("finite sliding with 30 cutbacks" FALSE "Maximum cutbacks" ${WORK_DIR}/finite-sliding-cutbacks.prm)
