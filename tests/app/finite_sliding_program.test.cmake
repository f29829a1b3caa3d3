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
#   Coulomb law at every pair); at least three such steps; the JSON
#   timings cover the run (check_timings());
# - the outputs of a turning or sliding part at every step (the balance of
#   the support reactions, the interface resultant and its moment against
#   the reaction on the block, the node pairs' CSV: see below);
# - 'Contact/Pairs = auto' on the same file: one interface detected at
#   every step, its force and moment those of the named pair (6 digits);
# - bad input: finite sliding with 'Contact/Tangential = penalty' (the
#   contact patch test of examples/step-2 with a Neo-Hooke law) stops with
#   a message naming the parameter, and
#   'Contact/Maximum cutbacks = 30' (out of [0, 20]) with deal.II's message
#   naming the file, the line and the entry.
include(${TEST_DIR}/program_checks.cmake)
set(RUN_TIMEOUT 600)
set(EXAMPLES ${SOURCE_DIR}/examples/parameters)
file(REMOVE_RECURSE ${WORK_DIR}/output)

run_dealvem("finite-sliding-block.prm" TRUE "Finite strain with finite sliding: 2 bodies, 1 named interface"
  ${EXAMPLES}/finite-sliding-block.prm)
set(base finite-sliding-block)
file(READ ${WORK_DIR}/output/${base}.json json)
string(JSON status GET "${json}" status)
string(JSON converged GET "${json}" converged_steps)
if(NOT status STREQUAL "complete" OR NOT converged EQUAL 12)
  message(FATAL_ERROR "FAIL finite sliding: status ${status}, ${converged} of 12 steps converged")
endif()
check_timings("finite sliding timings" "${json}" mesh "contact detection" setup report "finite sliding solve"
              postprocessing "output vtu" "output csv" "output json")
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

# --- the outputs a user of a sliding part reads, at every step: the base is
# held on boundary 2, the block is moved by its top (boundary 13) and loaded
# by nothing else, so
# - the reactions on 2 and 13 and the applied loads (none) balance in force
#   and in moment (about the moment point (0, 0), current positions);
# - the contact force on the block (the slave side) balances the reaction on
#   13 alone, in force and moment;
# - the node pairs' CSV has a row per pair whose force w (p n + tau t)
#   (weight, pressure, tangential traction, current normal n, t = (-n_y, n_x))
#   sums to the interface resultant, open rows carry nothing, and every
#   slipping row has |tau| = mu p (Coulomb)
foreach(s RANGE 1 12)
  string(JSON load_x GET "${json}" steps ${s} loads force_x)
  string(JSON load_y GET "${json}" steps ${s} loads force_y)
  string(JSON load_m GET "${json}" steps ${s} loads moment)
  foreach(q force_x force_y moment)
    string(JSON base_${q} GET "${json}" steps ${s} reactions boundary_2 ${q})
    string(JSON top_${q} GET "${json}" steps ${s} reactions boundary_13 ${q})
    string(JSON slave_${q} GET "${json}" steps ${s} interfaces 0 ${q})
  endforeach()
  check_balance("finite sliding, step ${s}: reactions + loads, x" 8 ${top_force_y} ${base_force_x} ${top_force_x} ${load_x})
  check_balance("finite sliding, step ${s}: reactions + loads, y" 8 ${top_force_y} ${base_force_y} ${top_force_y} ${load_y})
  check_balance("finite sliding, step ${s}: reactions + loads, moment" 8 ${top_moment} ${base_moment} ${top_moment} ${load_m})
  foreach(q force_x force_y moment)
    check_balance("finite sliding, step ${s}: contact on the block + reaction on its top, ${q}" 8 ${top_${q}}
      ${slave_${q}} ${top_${q}})
  endforeach()

  string(LENGTH "00${s}" len)
  math(EXPR cut "${len} - 3")
  string(SUBSTRING "00${s}" ${cut} 3 nnn)
  file(STRINGS ${WORK_DIR}/output/${base}-step-${nnn}-interface.csv rows)
  list(GET rows 0 header)
  if(NOT header STREQUAL "interface,pair,x,y,normal_x,normal_y,weight,gap,pressure,tangential_traction,status")
    message(FATAL_ERROR "FAIL finite sliding: ${base}-step-${nnn}-interface.csv has the header '${header}'")
  endif()
  list(REMOVE_AT rows 0)
  list(LENGTH rows n_rows)
  string(JSON n_pairs GET "${json}" steps ${s} pairs)
  if(NOT n_rows EQUAL n_pairs)
    message(FATAL_ERROR "FAIL finite sliding, step ${s}: ${n_rows} rows in the pairs' CSV, ${n_pairs} pairs")
  endif()
  set(sum_x "")
  set(sum_y "")
  set(n_slip 0)
  set(QUIET_CHECKS TRUE)
  foreach(row ${rows})
    string(REPLACE "," ";" f "${row}")
    list(GET f 4 nx)
    list(GET f 5 ny)
    list(GET f 6 w)
    list(GET f 8 p)
    list(GET f 9 tau)
    list(GET f 10 status)
    if(status STREQUAL "open")
      if(NOT p EQUAL 0 OR NOT tau EQUAL 0)
        message(FATAL_ERROR "FAIL finite sliding, step ${s}: an open pair with pressure ${p}, traction ${tau}")
      endif()
      continue()
    endif()
    if(NOT status MATCHES "^(stick|slip)$" OR NOT p GREATER 0)
      message(FATAL_ERROR "FAIL finite sliding, step ${s}: a pair '${status}' with pressure ${p}")
    endif()
    if(status STREQUAL "slip")
      decimal_product(0.3 ${p} mu_p)
      string(REGEX REPLACE "^-" "" abs_tau "${tau}")
      check_relative(${abs_tau} ${mu_p} 8 "finite sliding, step ${s}: a slipping pair's |tau| = mu p")
      math(EXPR n_slip "${n_slip} + 1")
    endif()
    decimal_product(${w} ${p} wp)
    decimal_product(${w} ${tau} wt)
    decimal_product(${wp} ${nx} wp_nx)
    decimal_product(${wp} ${ny} wp_ny)
    decimal_product(${wt} ${ny} wt_ny)
    decimal_product(${wt} ${nx} wt_nx)
    negated(${wt_ny} minus_wt_ny)
    list(APPEND sum_x ${wp_nx} ${minus_wt_ny})
    list(APPEND sum_y ${wp_ny} ${wt_nx})
  endforeach()
  unset(QUIET_CHECKS)
  negated(${slave_force_x} minus_fx)
  negated(${slave_force_y} minus_fy)
  # (the products keep nine digits: 1e-7)
  check_balance("finite sliding, step ${s}: the pairs' forces sum to the resultant, x" 7 ${slave_force_y}
    ${sum_x} ${minus_fx})
  check_balance("finite sliding, step ${s}: the pairs' forces sum to the resultant, y" 7 ${slave_force_y}
    ${sum_y} ${minus_fy})
  message(STATUS "PASS finite sliding, step ${s}: ${n_rows} rows, |tau| = mu p at the ${n_slip} slipping pairs")
endforeach()
message(STATUS "PASS finite sliding: reactions, loads and interface resultants in balance at every step; the pairs' CSV sums to the resultants")

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
string(REPLACE "set Base name      = finite-sliding-block" "set Base name      = finite-sliding-auto" auto_prm
  "${auto_prm}")
file(WRITE ${WORK_DIR}/finite-sliding-auto.prm "${auto_prm}")
run_dealvem("finite sliding with detected pairs" TRUE
  "the others detected in the current configuration at every pairing pass"
  ${WORK_DIR}/finite-sliding-auto.prm)
file(READ ${WORK_DIR}/output/finite-sliding-auto.json auto_json)
string(JSON auto_status GET "${auto_json}" status)
if(NOT auto_status STREQUAL "complete")
  message(FATAL_ERROR "FAIL finite sliding with detected pairs: status ${auto_status}")
endif()
# the detection finds the same faces as the named pair (top of the base,
# bottom of the block, grown to their corners): the same forces
foreach(s 1 6 12)
  foreach(c force_x force_y moment)
    string(JSON named_value GET "${json}" steps ${s} interfaces 0 ${c})
    string(JSON auto_value GET "${auto_json}" steps ${s} interfaces 0 ${c})
    check_relative(${named_value} ${auto_value} 6 "finite sliding, step ${s}: ${c} with detected pairs and named")
  endforeach()
  string(JSON detected GET "${auto_json}" steps ${s} detected_interfaces)
  if(NOT detected EQUAL 1)
    message(FATAL_ERROR "FAIL finite sliding with detected pairs, step ${s}: ${detected} interfaces detected, expected 1")
  endif()
endforeach()
message(STATUS "PASS finite sliding with detected pairs: one interface per step, the forces of the named pair")
# 'Contact/Maximum cutbacks' (FiniteSliding::Parameters::max_cutbacks) is an
# integer in [0, 20]: 30 stops the program naming the file, line and entry
string(REPLACE "subsection Contact" "subsection Contact\n  set Maximum cutbacks = 30" cutbacks_prm "${block_prm}")
file(WRITE ${WORK_DIR}/finite-sliding-cutbacks.prm "${cutbacks_prm}")
run_dealvem("finite sliding with 30 cutbacks" FALSE "Maximum cutbacks" ${WORK_DIR}/finite-sliding-cutbacks.prm)
