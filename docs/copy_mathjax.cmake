# Copies Debian's MathJax (libjs-mathjax) beside the manual's pages, without its unpacked sources and
# tests: cmake -D MATHJAX=/usr/share/javascript/mathjax -D DESTINATION=.../html/mathjax -P copy_mathjax.cmake
file(COPY ${MATHJAX}/ DESTINATION ${DESTINATION} FOLLOW_SYMLINK_CHAIN PATTERN unpacked EXCLUDE PATTERN test EXCLUDE)
