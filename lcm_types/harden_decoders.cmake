# Makes lcm-gen's C++ decoders reject an array count or string length that the bytes cannot
# hold, BEFORE they allocate. Run by CMakeLists.txt on every generated header:
#   cmake -DHEADER_DIR=<dir with the generated .hpp files> -P harden_decoders.cmake
#
# Why: lcm-gen (1.3.1, and still 1.5) trusts the counts it reads. `this->left.resize(this->
# motion_ticks)` runs before any element is read, so a forged count of -1 becomes a resize to
# (size_t)-1 (std::length_error out of decode(), through the LCM callback: the process dies),
# and a count of 32767 in a 100-byte message allocates megabytes it will never fill. A string
# length of 0 or less becomes assign(p, (size_t)-1): std::length_error again.
#
# The guard inserted before each resize, `count < 0 || count > maxlen - pos`, is exact for
# negative counts and sound for large ones: every element of every array in our types takes at
# least one byte, so a count above the bytes left cannot decode. The decoder then returns -1,
# which transport::decode() turns into a MalformedMessage like any truncated message. What it
# still allocates is bounded by the message's own size.
#
# If a new lcm-gen writes its decoders differently, the counts below stop matching and the
# build fails here, instead of leaving a decoder unguarded.
cmake_minimum_required(VERSION 3.22)
# Patterns below avoid ';' so that MATCHALL's results stay one list element per match.
if(NOT HEADER_DIR)
  message(FATAL_ERROR "harden_decoders.cmake: set HEADER_DIR")
endif()
file(GLOB headers ${HEADER_DIR}/*.hpp)
if(NOT headers)
  message(FATAL_ERROR "harden_decoders.cmake: no generated headers in ${HEADER_DIR}")
endif()

foreach(header ${headers})
  file(READ ${header} text)
  if(text MATCHES "touchline-hardened")
    continue() # already done (the script may run twice on the same output)
  endif()

  # Variable-length arrays: one `this-><array>.resize(this-><count>);` per array.
  string(REGEX MATCHALL "\\.resize\\(" resizes "${text}")
  string(REGEX MATCHALL "this->[A-Za-z0-9_]+\\.resize\\(this->[A-Za-z0-9_]+\\)" guardable "${text}")
  list(LENGTH resizes n_resizes)
  list(LENGTH guardable n_guardable)
  if(NOT n_resizes EQUAL n_guardable)
    message(FATAL_ERROR "harden_decoders.cmake: ${header} has ${n_resizes} resize calls but only "
                        "${n_guardable} of the form this->a.resize(this->n); update this script")
  endif()
  string(REGEX REPLACE
    "(this->[A-Za-z0-9_]+)\\.resize\\((this->[A-Za-z0-9_]+)\\);"
    "if (\\2 < 0 || \\2 > maxlen - pos) return -1; /* touchline-hardened */ \\1.resize(\\2);"
    text "${text}")

  # Strings: a length (which counts the terminating NUL) below 1 is malformed.
  string(REGEX MATCHALL "\\.assign\\(" assigns "${text}")
  string(REGEX MATCHALL "if\\(__[A-Za-z0-9_]+_len__ > maxlen - pos\\) return -1" checks "${text}")
  list(LENGTH assigns n_assigns)
  list(LENGTH checks n_checks)
  if(NOT n_assigns EQUAL n_checks)
    message(FATAL_ERROR "harden_decoders.cmake: ${header} has ${n_assigns} string assigns but "
                        "${n_checks} length checks of the expected form; update this script")
  endif()
  string(REGEX REPLACE
    "if\\((__[A-Za-z0-9_]+_len__) > maxlen - pos\\) return -1;"
    "if(\\1 < 1 || \\1 > maxlen - pos) return -1; /* touchline-hardened */"
    text "${text}")

  file(WRITE ${header} "${text}")
endforeach()
