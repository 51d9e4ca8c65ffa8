# Sourced by the benchmark scripts: builds the runtime in Release (no tests) and installs it into
# $out/prefix, logs in $out. Needs $here (the repository) and $out.
cmake -S "$here/runtime" -B "$out/runtime" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  -DCMAKE_INSTALL_PREFIX="$out/prefix" > "$out/runtime.configure.log"
cmake --build "$out/runtime" -j 2 > "$out/runtime.build.log"
cmake --install "$out/runtime" > "$out/runtime.install.log"
