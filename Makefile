# smallmlt build. `make run` renders the default scene, `make test` runs all
# tests; both install missing Debian packages first (`make deps`).
# SAN=1 builds with AddressSanitizer and UndefinedBehaviorSanitizer.

CXX      ?= g++
SAN      ?= 0
JOBS     ?= $(shell nproc)
BUILD    := $(if $(filter 1,$(SAN)),build-san,build)
CXXFLAGS := -std=c++17 -O2 -g -Wall -Wextra -Werror -Isrc -Icl/core -MMD -MP
LDLIBS   := -lOpenCL -ltinyobjloader -ltinyexr -lstb -lpugixml -lpthread
ifeq ($(SAN),1)
CXXFLAGS += -O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
LDFLAGS  += -fsanitize=address,undefined
export LSAN_OPTIONS := suppressions=$(CURDIR)/test/lsan.supp print_suppressions=0
# Once Mesa's OpenCL is installed, the ICD loader opens it in every process,
# and it opens and closes llvmpipe's pipe driver, whose allocations
# LeakSanitizer can then name by no module: the tests on PoCL see PoCL's
# ICD alone (the rusticl runs name their own, whose modules stay loaded).
export OCL_ICD_VENDORS := /etc/OpenCL/vendors/pocl.icd
endif

DEB_PACKAGES := g++ make pocl-opencl-icd mesa-opencl-icd ocl-icd-opencl-dev opencl-headers \
                libstb-dev gnuplot-nox libtinyobjloader-dev libtinyexr-dev libgtest-dev \
                libopenmpi-dev openmpi-bin libpugixml-dev python3
# Mesa's OpenCL (rusticl) on the CPU (llvmpipe), as the only platform: the
# compiler of Linux's small GPUs (doc/devices.md).
RUSTICL_ENV  := OCL_ICD_VENDORS=/etc/OpenCL/vendors/rusticl.icd RUSTICL_ENABLE=swrast

# `make fuzz` only: libFuzzer comes with clang's runtime libraries.
FUZZ_PACKAGES := clang libclang-rt-dev
FUZZ_SECONDS  ?= 60
FUZZ_SRC      := $(addprefix src/scene/,scene.cpp obj_loader.cpp mtl_loader.cpp mtl_models.cpp \
                   material.cpp plastic_coat.cpp ply_loader.cpp text_parse.cpp bvh.cpp \
                   device_scene.cpp sample_layout.cpp texture.cpp mitsuba_xml.cpp \
                   mitsuba_transform.cpp mitsuba_shapes.cpp \
                   mitsuba_bsdfs.cpp mitsuba_conductors.cpp mitsuba_scene.cpp mitsuba_textures.cpp)
FUZZ_TARGETS  := fuzz_scene fuzz_mitsuba

# Kernel files: the product's (cl/, by stage) and the test binary's probes.
CL_FILES   := $(sort $(wildcard cl/*/*.h cl/*/*.cl))
TEST_CL    := $(sort $(wildcard test/cl/*.cl))
LIB_SRC    := $(filter-out src/app/main.cpp src/mpi/%,$(wildcard src/*/*.cpp))
MPI_SRC    := $(wildcard src/mpi/*.cpp)
MPI_OBJ    := $(MPI_SRC:src/%.cpp=$(BUILD)/obj/%.o)
LIB_OBJ    := $(LIB_SRC:src/%.cpp=$(BUILD)/obj/%.o) $(BUILD)/obj/gen/kernel_sources.o
TEST_SRC   := $(wildcard test/*.cpp)
TEST_OBJ   := $(TEST_SRC:test/%.cpp=$(BUILD)/obj/test/%.o) $(BUILD)/obj/gen/test_kernel_sources.o
BIN        := $(BUILD)/smallmlt
TEST_BIN   := $(BUILD)/smallmlt_tests
# Test code is mostly calls into the library and the device: compiled
# lighter, it builds in a third less time (sanitizer builds keep -g).
TEST_OPT   := $(if $(filter 1,$(SAN)),,-O1 -g0)
# smallmlt-mpi, the same renderer over MPI ranks, when Open MPI is installed.
MPICXX     := $(shell command -v mpicxx 2>/dev/null)
MPI_BIN    := $(if $(MPICXX),$(BUILD)/smallmlt-mpi)

.PHONY: all deps deps-fuzz run test test-rusticl bench bench-quick mutants fuzz format clean

all: $(BIN) $(MPI_BIN)

deps deps-fuzz: PACKAGES = $(if $(filter deps-fuzz,$@),$(FUZZ_PACKAGES),$(DEB_PACKAGES))
deps deps-fuzz:
	@missing=$$(for p in $(PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; \
	  done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

$(BUILD)/gen/kernel_sources.cpp: $(CL_FILES) src/device/embed_kernels.sh
	@mkdir -p $(dir $@)
	sh src/device/embed_kernels.sh kProductKernelFiles $(CL_FILES) > $@.tmp && mv $@.tmp $@

$(BUILD)/gen/test_kernel_sources.cpp: $(TEST_CL) src/device/embed_kernels.sh
	@mkdir -p $(dir $@)
	sh src/device/embed_kernels.sh kTestKernelFiles $(TEST_CL) > $@.tmp && mv $@.tmp $@

$(BUILD)/obj/gen/%.o: $(BUILD)/gen/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: src/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(BUILD)/obj/test/%.o: test/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(TEST_OPT) -Itest -c $< -o $@

$(BUILD)/libsmallmlt.a: $(LIB_OBJ)
	ar rcs $@ $^

$(BIN): $(BUILD)/obj/app/main.o $(BUILD)/libsmallmlt.a
	$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS)

$(BUILD)/obj/mpi/%.o: src/mpi/%.cpp
	@mkdir -p $(dir $@)
	OMPI_CXX=$(CXX) $(MPICXX) $(CXXFLAGS) -DOMPI_SKIP_MPICXX -c $< -o $@

$(BUILD)/smallmlt-mpi: $(MPI_OBJ) $(BUILD)/libsmallmlt.a
	OMPI_CXX=$(CXX) $(MPICXX) $(LDFLAGS) $^ -o $@ $(LDLIBS)

$(TEST_BIN): $(TEST_OBJ) $(BUILD)/libsmallmlt.a
	$(CXX) $(LDFLAGS) $^ -o $@ -lgtest -lgtest_main $(LDLIBS)

run: deps
	$(MAKE) $(BIN)
	@mkdir -p out
	$(BIN) render scenes/cornell-water.scene --time 40 --out out/cornell-water.png

# The sub-make reads this file again after `deps`, so that `all` includes
# smallmlt-mpi once deps has installed Open MPI.
test: deps
	$(MAKE) -j$(JOBS) all $(TEST_BIN)
	SMALLMLT_BIN=$(BIN) sh test/run_all.sh $(TEST_BIN)

# Every test on Mesa's OpenCL alone (make test runs a subset there).
test-rusticl: deps
	$(MAKE) -j$(JOBS) all $(TEST_BIN)
	$(RUSTICL_ENV) RUSTICL_TESTS=none SMALLMLT_BIN=$(BIN) sh test/run_all.sh $(TEST_BIN)

bench: deps
	$(MAKE) all
	sh bench/all.sh $(BIN)

bench-quick: deps
	$(MAKE) all
	QUICK=1 sh bench/all.sh $(BIN)

# Applies each deliberate bug of test/mutants.txt in a copy of the project
# (build/mutants/tree) and checks that some test fails; not part of `make test`.
mutants: deps
	sh test/mutants.sh

# Fuzzes the scene, OBJ and MTL loaders for FUZZ_SECONDS (default 60) from
# the seed corpus in test/fuzz/corpus; findings are written as crash-* files.
build/fuzz/%: test/fuzz/%.cpp test/fuzz/fuzz_files.hpp $(FUZZ_SRC)
	@mkdir -p $(dir $@)
	clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -Isrc -Icl/core $(filter %.cpp,$^) -o $@ \
	    -ltinyobjloader -lstb -lpugixml

# Each target for FUZZ_SECONDS from its seed corpus (test/fuzz/corpus/TARGET).
fuzz: deps deps-fuzz
	$(MAKE) $(addprefix build/fuzz/,$(FUZZ_TARGETS))
	for t in $(FUZZ_TARGETS); do \
	    mkdir -p build/fuzz/corpus-$$t && cp test/fuzz/corpus/$$t/* build/fuzz/corpus-$$t/ && \
	    (cd build/fuzz && ./$$t -max_total_time=$(FUZZ_SECONDS) -max_len=65536 \
	        -print_final_stats=1 corpus-$$t) || exit 1; \
	done

format:
	clang-format -i src/*/*.cpp src/*/*.hpp test/*.cpp test/*.hpp cl/*/*.cl cl/*/*.h test/cl/*.cl

clean:
	rm -rf build build-san

-include $(wildcard $(BUILD)/obj/*/*.d)
