# 3 s in Release (two walls of 14 000 DoFs, 12 + 1 solves). The timeout
# makes a return of the old behaviour a failure: before the pairs of a
# cycle were held and the polish was bounded, this wall ran the polish of
# the globalized solve to its limit (tens of minutes). Under the
# sanitizers contact/state_update runs the rule that holds the pairs, and
# contact/globalized_solve the polish.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow" TIMEOUT 120)
