# Writes a C++ source that defines collide2d::tool::NAME, a string holding the text of INPUT:
#   cmake -DINPUT=PAGE.html -DOUTPUT=PAGE.cpp -DNAME=kPage -P embed.cmake
file(READ "${INPUT}" text)
file(WRITE "${OUTPUT}" "// Made from ${INPUT} by cmake/embed.cmake.\nnamespace collide2d::tool {\nextern const char ${NAME}[];\nconst char ${NAME}[] = R\"embed(${text})embed\";\n}  // namespace collide2d::tool\n")
