# Lays the source tree out in MOD_DIR as the Addon Manager's clone of the repository would be: no build, no core.
file(REMOVE_RECURSE ${MOD_DIR})
file(COPY ${SOURCE_DIR}/ DESTINATION ${MOD_DIR}
     PATTERN ".git" EXCLUDE PATTERN "build" EXCLUDE PATTERN "build-*" EXCLUDE PATTERN "__pycache__" EXCLUDE
     PATTERN "fabguide_core*.so" EXCLUDE)
