# 4 s in Release. Before the polish of the globalized solve was bounded,
# this wall ran to the polish's old limit (tens of minutes): the timeout
# makes that a failure. At -O1 under the sanitizers its 60 or so solves
# take minutes; contact/globalized_solve runs the same code there.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow" TIMEOUT 120)
