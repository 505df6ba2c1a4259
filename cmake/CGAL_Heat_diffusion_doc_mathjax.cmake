# Copies the part of MathJax 2 that the manual's pages load from MATHJAX_DIR (Debian:
# libjs-mathjax) into HTML_DIR/mathjax, where the
# Doxyfile's MATHJAX_RELPATH points. The manual then typesets its formulas without
# network access, and keeps doing so once installed (`cmake --install`) or copied to
# another machine, whether or not that machine has MathJax.
#
# The part: the core, the TeX input with its extensions (AMSmath, AMSsymbols and those
# TeX loads on demand), the tex2jax preprocessor, the menu and zoom, the English
# strings, and the SVG output with its TeX glyphs. The SVG output draws the glyphs
# from JavaScript data: the HTML-CSS output needs MathJax's web fonts, which Chromium
# refuses to load from file:// pages (and takes from the system's fonts-mathjax when
# installed, so that the manual would look right only where that package is).
#
# Run by the target `doc` (cmake -DMATHJAX_DIR=... -DHTML_DIR=... -P this file) and
# included by CGAL_Heat_diffusion_check_doc.cmake after Doxygen.
foreach(var MATHJAX_DIR HTML_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CGAL_Heat_diffusion_doc_mathjax.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT EXISTS "${MATHJAX_DIR}/MathJax.js")
  message(FATAL_ERROR "${MATHJAX_DIR}/MathJax.js does not exist (Debian: libjs-mathjax)")
endif()

set(mathjax_out "${HTML_DIR}/mathjax")
file(COPY "${MATHJAX_DIR}/MathJax.js" DESTINATION "${mathjax_out}")
file(COPY "${MATHJAX_DIR}/extensions" DESTINATION "${mathjax_out}")
file(COPY "${MATHJAX_DIR}/localization/en" DESTINATION "${mathjax_out}/localization")
file(COPY "${MATHJAX_DIR}/jax/input/TeX" DESTINATION "${mathjax_out}/jax/input")
file(COPY "${MATHJAX_DIR}/jax/element" DESTINATION "${mathjax_out}/jax")
file(COPY "${MATHJAX_DIR}/jax/output/SVG" DESTINATION "${mathjax_out}/jax/output"
     PATTERN "fonts" EXCLUDE)
file(COPY "${MATHJAX_DIR}/jax/output/SVG/fonts/TeX" DESTINATION "${mathjax_out}/jax/output/SVG/fonts")
# MathJax is under the Apache License 2.0, which asks for its notice to go with copies.
foreach(notice "${MATHJAX_DIR}/LICENSE" "/usr/share/doc/libjs-mathjax/copyright")
  if(EXISTS "${notice}")
    file(COPY "${notice}" DESTINATION "${mathjax_out}")
  endif()
endforeach()
