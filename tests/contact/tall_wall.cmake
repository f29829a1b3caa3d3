# 3 s in Release, 27 s under the sanitizers at -O1 (two walls of 14 000
# DoFs, 12 + 1 solves). The timeout makes a return of the old behaviour a
# failure: before the pairs of a cycle were held and the polish was
# bounded, this wall ran the polish of the globalized solve to its limit
# (tens of minutes).
set_tests_properties(${_test} PROPERTIES TIMEOUT 120)
