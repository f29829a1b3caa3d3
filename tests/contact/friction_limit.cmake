# Five Coulomb solves near the friction limit, two of them through the
# friction-coefficient continuation (many Newton iterations each): about
# 5 s in Release, 4 minutes at -O0 under the sanitizers (checked clean
# there when it was added). The sanitizer run leaves it to the normal
# suite; contact/friction and contact/active_set_loop run the friction code
# under the sanitizers.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
