// The glare and io libraries' copies of the vector-loop attribute are the
// retina library's (each library stands alone, so each has its own header).
#include <gtest/gtest.h>

#include <string>

#define EYESTREAM_STRING_OF(...) #__VA_ARGS__
#define EYESTREAM_EXPANDED(...) EYESTREAM_STRING_OF(__VA_ARGS__)

#include "retina/vector_clones.hpp"
static const std::string kRetinas = EYESTREAM_EXPANDED(EYESTREAM_VECTOR_CLONES);
#undef EYESTREAM_VECTOR_CLONES
#include "glare/vector_clones.hpp"
static const std::string kGlares = EYESTREAM_EXPANDED(EYESTREAM_VECTOR_CLONES);
#undef EYESTREAM_VECTOR_CLONES
#include "io/vector_clones.hpp"
static const std::string kIos = EYESTREAM_EXPANDED(EYESTREAM_VECTOR_CLONES);

namespace eyestream {
namespace {

TEST(VectorClones, TheGlareAndIoLibrariesCopiesAreTheRetinas) {
  EXPECT_EQ(kGlares, kRetinas);
  EXPECT_EQ(kIos, kRetinas);
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
  EXPECT_NE(kRetinas.find("x86-64-v4"), std::string::npos) << kRetinas;
#endif
}

}  // namespace
}  // namespace eyestream
