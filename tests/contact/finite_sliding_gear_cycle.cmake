# Three finite-sliding steps of a gear pair where a tooth pair leaves
# contact, at 15k DoFs, and three small-strain contact solves: 40 s of CPU
# in Release, so the sanitizer run leaves it to the normal suite, like
# contact/finite_sliding.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
# One base pitch in 16 roll angles (both double-contact zones, a pair
# leaving and one entering). With the flanks graded to 0.01: 54k DoFs, 13.6
# min of CPU in Release (torque within 0.047 %, shares within 3.2e-4, peak
# pressure within 1.3 %). Graded to 0.005, the default since 2026-11-30:
# 98k DoFs, 26.6 min (torque 0.049 %, shares 3.3e-4, peak pressure 1.8 %
# at the second tooth pair at roll -8.27 degrees, a/h 13): the peak
# pressure fails issue 41's 1 % here; open.) With --h 0.0025 (2026-11-30,
# after the short-chord fix of FiniteStrainContact: 187k DoFs, 44 min of
# CPU): torque within 0.049 %, shares within 3.4e-4, 20 of 21 resolved
# zones within 0.63 % (single contact +0.06 to +0.63 %, finite strain
# against small strain at p/E = 0.6 %), the last, pair 1 leaving on the
# pinion's relief at s_k = 1.79 (9 % of the load, a/h 14), 1.5 %: open.
add_test(NAME contact/finite_sliding_gear_cycle-pitch COMMAND ${_test_command} --pitch WORKING_DIRECTORY ${_workdir})
set_tests_properties(contact/finite_sliding_gear_cycle-pitch PROPERTIES LABELS "contact;long" TIMEOUT 7200)
