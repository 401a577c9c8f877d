#pragma once
// Golden-image tests: decoded pixels against tests/golden/<name>.png, compared as image_compare.h does.
// PHYSLTL_UPDATE_GOLDENS=1 (tests/run --update-goldens) rewrites the golden instead of comparing; nothing
// else ever does.

#include "physltl/render/image_compare.h"

#include <gtest/gtest.h>

#include <string>

namespace physltl::render {

// On failure writes <name>.actual.png and <name>.diff.png into PHYSLTL_TEST_OUTPUT_DIR and names them.
::testing::AssertionResult matches_golden(const Image& actual, const std::string& name, const Tolerance& tolerance = {});

}  // namespace physltl::render
