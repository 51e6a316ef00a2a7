# SPDX-License-Identifier: Apache-2.0
# The AUTO/ON/OFF cache options of the optional parts (TOROID_PYTHON,
# TOROID_EMBREE), read the same way by each part's CMakeLists.txt:
#
#   toroid_feature_mode(TOROID_X mode)   # mode: AUTO, ON or OFF
#   if(mode STREQUAL "OFF")
#     return()
#   endif()
#   ... find what the part needs ...
#   if(<something is missing>)
#     toroid_feature_unavailable(${mode} "TOROID_X=ON, but ..." "toroid: the part is skipped: ...")
#     return()
#   endif()
include_guard(GLOBAL)

# Sets <out> to AUTO, ON or OFF from the value of the cache option <option>:
# AUTO in any case; ON for a true constant (ON, YES, TRUE, Y, 1); OFF for a
# false one (OFF, NO, FALSE, N, 0) or nothing. Any other value is an error.
function(toroid_feature_mode option out)
  string(TOUPPER "${${option}}" mode)
  if(mode STREQUAL "AUTO")
    set(${out} AUTO PARENT_SCOPE)
  elseif(mode MATCHES "^(ON|YES|TRUE|Y|1)$")
    set(${out} ON PARENT_SCOPE)
  elseif(mode MATCHES "^(OFF|NO|FALSE|N|0|)$")
    set(${out} OFF PARENT_SCOPE)
  else()
    message(FATAL_ERROR "${option} must be AUTO, ON or OFF, got '${${option}}'")
  endif()
endfunction()

# A part that cannot be built in this configuration: under ON (the part is
# required) stops with <error>; under AUTO says <status> and the caller
# returns, building nothing.
function(toroid_feature_unavailable mode error status)
  if(mode STREQUAL "ON")
    message(FATAL_ERROR "${error}")
  endif()
  message(STATUS "${status}")
endfunction()

# Sets <out> to TRUE in a sanitized build (TOROID_SANITIZE, TOROID_FUZZ or
# TOROID_SANITIZE_THREAD), which the parts built on uninstrumented libraries
# (Python, MPI) leave out.
function(toroid_sanitized_build out)
  if(TOROID_SANITIZE OR TOROID_FUZZ OR TOROID_SANITIZE_THREAD)
    set(${out} TRUE PARENT_SCOPE)
  else()
    set(${out} FALSE PARENT_SCOPE)
  endif()
endfunction()
