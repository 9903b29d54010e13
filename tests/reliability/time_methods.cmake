# Time-integration methods are plug-ins chosen by name (timeint/MethodRegistry.hpp): a
# misspelt name is refused by the deck's key with every registered method and the closest
# one, and a key that belongs to another method than the chosen one is refused by its name.
# Nothing is written. (Uses capsula_add_refusal_test and _demo, _tether2d of bad_input.cmake.)
set(_registered_methods "RKF45, DormandPrince45, RK4, ROS34PW2, ROS2, Auto")

capsula_add_refusal_test(reliability_unknown_time_method_names_the_key_and_the_closest
  MATCHES "'Time integration/Method' = \"ROS34PW3\" is invalid: it must be one of: ${_registered_methods} \\(did you mean \"ROS34PW2\"\\?\\)"
  COMMAND ${_demo} --set "Time integration/Method=ROS34PW3")

capsula_add_refusal_test(reliability_tether2d_unknown_time_method_names_the_key_and_the_closest
  MATCHES "'Time integration/Method' = \"DormandPrince54\" is invalid: it must be one of: ${_registered_methods} \\(did you mean \"DormandPrince45\"\\?\\)"
  COMMAND ${_tether2d} --set "Time integration/Method=DormandPrince54")

capsula_add_refusal_test(reliability_key_of_another_time_method_is_refused
  MATCHES "'Time integration/Linear tolerance' = 0\\.1 applies to Method ROS34PW2, ROS2, Auto only \\('Time integration/Method' is RKF45\\): leave it at its default 0\\.01\\."
  COMMAND ${_demo} --set "Time integration/Method=RKF45" --set "Time integration/Linear tolerance=0.1")
