# Decides the default of CAVITY_BUILD_PYTHON: the module is built for Debian's interpreter
# (/usr/bin/python3, where python3-numpy installs numpy), never the first python3 on PATH (a
# pyenv or venv interpreter would need its own numpy and its own build of the module).
set(CAVITY_PYTHON_EXECUTABLE "/usr/bin/python3" CACHE FILEPATH
    "Interpreter the cavity Python module is built for")

set(CAVITY_PYTHON_AVAILABLE OFF)
if(EXISTS "${CAVITY_PYTHON_EXECUTABLE}")
  execute_process(COMMAND "${CAVITY_PYTHON_EXECUTABLE}" -c "import numpy"
                  RESULT_VARIABLE _cavity_numpy_status OUTPUT_QUIET ERROR_QUIET)
  # pybind11 looks for Python itself; point FindPython at the chosen interpreter first.
  set(Python_EXECUTABLE "${CAVITY_PYTHON_EXECUTABLE}")
  set(PYBIND11_FINDPYTHON ON)
  find_package(Python 3 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  # An ASan/UBSan module cannot be loaded by an uninstrumented interpreter.
  if(_cavity_numpy_status EQUAL 0 AND pybind11_FOUND AND NOT CAVITY_SANITIZE)
    set(CAVITY_PYTHON_AVAILABLE ON)
  endif()
  unset(_cavity_numpy_status)
endif()
