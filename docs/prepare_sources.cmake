# Copies the Markdown the manual is built from into OUT/src, with the links a browser of the manual
# follows rewritten: the audits to their HTML pages, files of the source tree that are not pages to
# the text in the checkout. Run by the docs target: cmake -D SOURCE=... -D OUT=... -P prepare_sources.cmake
file(READ ${SOURCE}/README.md readme)
string(REPLACE "](generated/AUDIT.md)" "](audit/parkin2023.html)" readme "${readme}")
string(REPLACE "](generated/spinning/AUDIT.md)" "](audit/spinning.html)" readme "${readme}")
string(REPLACE "](generated/billiards/kernels.hpp)" "](kernels_8hpp.html)" readme "${readme}")
string(REPLACE "](generated/audit.json)" "](file://${SOURCE}/generated/audit.json)" readme "${readme}")
string(REPLACE "](LICENSE)" "](file://${SOURCE}/LICENSE)" readme "${readme}")
string(REPLACE "](bench/RESULTS.md)" "](RESULTS.md)" readme "${readme}")
file(WRITE ${OUT}/src/README.md "${readme}")
file(READ ${SOURCE}/bench/RESULTS.md results)
file(WRITE ${OUT}/src/RESULTS.md "${results}")
file(READ ${SOURCE}/examples/README.md examples)
string(REGEX REPLACE "^# examples" "# The examples {#examples_page}" examples "${examples}")
file(WRITE ${OUT}/src/examples.md "${examples}")
