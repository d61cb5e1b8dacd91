// The crease rules of Subdivision/Crease.h, each function on its own: against
// OpenSubdiv's Sdc::Crease over sweeps of sharpness values (smooth,
// fractional, integral, infinite) and valences, with uniform and Chaikin
// decay; without OpenSubdiv, against closed-form cases.
#include <CGAL_ext/Subdivision/Crease.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
#include <opensubdiv/sdc/crease.h>
#endif

namespace crease_tests {

namespace {

namespace C = CGAL_ext::Subdivision::Crease;
using CGAL_ext::Crease_method;
using CGAL_ext::infinitely_sharp;

// Sharpness values that exercise every branch: smooth (negative and 0),
// fractional below and above 1, integral, just below and at infinity, beyond.
const std::vector<float>& sharpness_values()
{
  static const std::vector<float> values = {-1.0f, 0.0f,  1e-6f, 0.1f,  0.25f, 0.5f,  0.999f, 1.0f,
                                            1.001f, 1.2f, 1.5f,  2.0f,  2.5f,  3.7f,  9.0f,   9.5f,
                                            9.999f, 10.0f, 10.5f, 100.0f};
  return values;
}

// `count` random edge sharpnesses around a vertex, mostly from the values
// above, some smooth, some random in (0, 11).
std::vector<float> random_ring(std::mt19937& rng, unsigned count)
{
  const std::vector<float>& values = sharpness_values();
  std::uniform_int_distribution<std::size_t> pick(0, values.size() + 3);
  std::uniform_real_distribution<float> any(0.0f, 11.0f);
  std::vector<float> ring(count);
  for (float& s : ring) {
    const std::size_t i = pick(rng);
    s = i < values.size() ? values[i] : (i == values.size() ? any(rng) : 0.0f);
  }
  return ring;
}

// ----------------------------------------------------------------- closed form

TEST(Crease, UniformDecayClosedForm)
{
  EXPECT_EQ(C::subdivide_uniform_sharpness(-2.0f), 0.0f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(0.0f), 0.0f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(0.5f), 0.0f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(1.0f), 0.0f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(2.5f), 1.5f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(9.5f), 8.5f);
  EXPECT_EQ(C::subdivide_uniform_sharpness(10.0f), infinitely_sharp);
  EXPECT_EQ(C::subdivide_uniform_sharpness(25.0f), infinitely_sharp);
  for (float s : sharpness_values()) {
    EXPECT_EQ(C::subdivide_vertex_sharpness(s), C::subdivide_uniform_sharpness(s));
    // Uniform decay ignores the neighbourhood.
    const float ring[3] = {s, 2.0f, 0.5f};
    EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::uniform, s, 3, ring),
              C::subdivide_uniform_sharpness(s));
  }
}

TEST(Crease, ChaikinDecayClosedForm)
{
  // Alone among semi-sharp edges, or at a vertex of one edge: s - 1.
  const float alone[3] = {2.5f, 0.0f, infinitely_sharp};
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 2.5f, 3, alone), 1.5f);
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 0.5f, 1, alone), 0.0f);
  // With one other semi-sharp edge: ¾ 3 + ¼ 1 − 1 = 1.5, and ¾ 1 + ¼ 3 − 1 = 0.5.
  const float pair[4] = {3.0f, 1.0f, 0.0f, 0.0f};
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 3.0f, 4, pair), 1.5f);
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 1.0f, 4, pair), 0.5f);
  // Smooth and infinite stay.
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 0.0f, 4, pair), 0.0f);
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 12.0f, 4, pair), infinitely_sharp);
  // The sum form agrees with the one-by-one form.
  C::Semi_sharp_edges around;
  for (float s : pair)
    around.add(s);
  EXPECT_EQ(around.count, 2u);
  EXPECT_EQ(around.sum, 4.0f);
  EXPECT_EQ(C::subdivide_edge_sharpness_at_vertex(Crease_method::chaikin, 3.0f, 4, around), 1.5f);
}

TEST(Crease, RuleTable)
{
  using R = C::Rule;
  EXPECT_EQ(C::vertex_rule(0.0f, 0u), R::smooth);
  EXPECT_EQ(C::vertex_rule(0.0f, 1u), R::dart);
  EXPECT_EQ(C::vertex_rule(0.0f, 2u), R::crease);
  EXPECT_EQ(C::vertex_rule(0.0f, 3u), R::corner);
  EXPECT_EQ(C::vertex_rule(-1.0f, 7u), R::corner);
  for (unsigned n = 0; n < 5; ++n)
    EXPECT_EQ(C::vertex_rule(0.3f, n), R::corner);
  const float ring[5] = {0.0f, 2.0f, -1.0f, 0.5f, 0.0f};
  EXPECT_EQ(C::vertex_rule(0.0f, 5, ring), R::crease);
  EXPECT_EQ(C::vertex_rule(0.0f, 2, ring), R::dart);
  EXPECT_EQ(C::vertex_rule(1.0f, 1, ring), R::corner);
}

TEST(Crease, FractionalWeightClosedForm)
{
  const float parent[4] = {0.5f, 2.0f, 0.0f, 0.25f};
  const float child[4] = {0.0f, 1.0f, 0.0f, 0.0f};
  // Nothing decays to smooth: 0.
  EXPECT_EQ(C::fractional_weight_at_vertex(0.0f, 0.0f, 1, parent + 1, child + 1), 0.0f);
  // Edges 0.5 and 0.25 decay: their mean.
  EXPECT_EQ(C::fractional_weight_at_vertex(0.0f, 0.0f, 4, parent, child), 0.375f);
  // The vertex decays too: (0.75 + 0.5 + 0.25) / 3.
  EXPECT_EQ(C::fractional_weight_at_vertex(0.75f, 0.0f, 4, parent, child), 0.5f);
  // Clamped to 1.
  const float heavy[1] = {3.0f}, gone[1] = {0.0f};
  EXPECT_EQ(C::fractional_weight_at_vertex(0.0f, 0.0f, 1, heavy, gone), 1.0f);
}

TEST(Crease, EdgePointRule)
{
  for (Crease_method m : {Crease_method::uniform, Crease_method::chaikin}) {
    EXPECT_FALSE(C::edge_point_is_crease(m, 0.0f, 0.0f, 0.0f));
    EXPECT_FALSE(C::edge_point_is_crease(m, 0.5f, 0.0f, 0.0f));
    EXPECT_TRUE(C::edge_point_is_crease(m, 1.0f, 0.0f, 0.0f));
    EXPECT_TRUE(C::edge_point_is_crease(m, infinitely_sharp, infinitely_sharp, infinitely_sharp));
  }
  // Chaikin can keep an edge below 1 sharp at both ends (sharper neighbours).
  EXPECT_TRUE(C::edge_point_is_crease(Crease_method::chaikin, 0.9f, 0.1f, 0.2f));
  EXPECT_FALSE(C::edge_point_is_crease(Crease_method::chaikin, 0.9f, 0.1f, 0.0f));
  EXPECT_FALSE(C::edge_point_is_crease(Crease_method::uniform, 0.9f, 0.1f, 0.2f));
  // Chaikin can also take one child of an edge above 1 to 0: then no crease.
  EXPECT_FALSE(C::edge_point_is_crease(Crease_method::chaikin, 1.2f, 0.0f, 0.2f));
  EXPECT_TRUE(C::edge_point_is_crease(Crease_method::chaikin, 1.2f, 0.05f, 0.2f));
}

// ----------------------------------------------------------------- OpenSubdiv

#ifdef CGAL_EXT_HAVE_OPENSUBDIV
namespace Sdc = OpenSubdiv::Sdc;

Sdc::Crease osd_crease(Crease_method method)
{
  Sdc::Options options;
  options.SetCreasingMethod(method == Crease_method::chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                             : Sdc::Options::CREASE_UNIFORM);
  return Sdc::Crease(options);
}

C::Rule from_osd(Sdc::Crease::Rule r)
{
  switch (r) {
  case Sdc::Crease::RULE_SMOOTH:
    return C::Rule::smooth;
  case Sdc::Crease::RULE_DART:
    return C::Rule::dart;
  case Sdc::Crease::RULE_CREASE:
    return C::Rule::crease;
  default:
    return C::Rule::corner;
  }
}

TEST(CreaseOpenSubdiv, Predicates)
{
  std::mt19937 rng(1);
  std::vector<float> values = sharpness_values();
  std::uniform_real_distribution<float> any(-1.0f, 12.0f);
  for (int i = 0; i < 1000; ++i)
    values.push_back(any(rng));
  for (float s : values) {
    SCOPED_TRACE(s);
    EXPECT_EQ(C::is_smooth(s), Sdc::Crease::IsSmooth(s));
    EXPECT_EQ(C::is_sharp(s), Sdc::Crease::IsSharp(s));
    EXPECT_EQ(C::is_infinite(s), Sdc::Crease::IsInfinite(s));
    EXPECT_EQ(C::is_semi_sharp(s), Sdc::Crease::IsSemiSharp(s));
  }
  EXPECT_EQ(infinitely_sharp, Sdc::Crease::SHARPNESS_INFINITE);
}

TEST(CreaseOpenSubdiv, UniformAndVertexDecay)
{
  std::mt19937 rng(2);
  std::vector<float> values = sharpness_values();
  std::uniform_real_distribution<float> any(-1.0f, 12.0f);
  for (int i = 0; i < 10000; ++i)
    values.push_back(any(rng));
  for (Crease_method m : {Crease_method::uniform, Crease_method::chaikin}) {
    const Sdc::Crease osd = osd_crease(m);
    for (float s : values) {
      SCOPED_TRACE(s);
      EXPECT_EQ(C::subdivide_uniform_sharpness(s), osd.SubdivideUniformSharpness(s));
      EXPECT_EQ(C::subdivide_vertex_sharpness(s), osd.SubdivideVertexSharpness(s));
    }
  }
}

// Every edge of random rings of valence 1 to 12: the child sharpness at the
// ring's vertex, bit for bit (both sum the semi-sharp edges in ring order).
TEST(CreaseOpenSubdiv, EdgeDecayAtVertex)
{
  std::mt19937 rng(3);
  int compared = 0;
  for (Crease_method m : {Crease_method::uniform, Crease_method::chaikin}) {
    const Sdc::Crease osd = osd_crease(m);
    for (unsigned n = 1; n <= 12; ++n) {
      for (int trial = 0; trial < 400; ++trial) {
        const std::vector<float> ring = random_ring(rng, n);
        for (unsigned i = 0; i < n; ++i) {
          const float ours = C::subdivide_edge_sharpness_at_vertex(m, ring[i], n, ring.data());
          const float theirs = osd.SubdivideEdgeSharpnessAtVertex(ring[i], int(n), ring.data());
          ASSERT_EQ(ours, theirs) << "valence " << n << " edge " << i << " sharpness " << ring[i];
          ++compared;
        }
        // OpenSubdiv's all-edges form gives the same values.
        std::vector<float> children(n);
        osd.SubdivideEdgeSharpnessesAroundVertex(int(n), ring.data(), children.data());
        // (It copies a ring without semi-sharp edges as is, where the one-edge
        // form makes smooth values 0 and infinite ones 10: compare those by kind.)
        for (unsigned i = 0; i < n; ++i) {
          const float ours = C::subdivide_edge_sharpness_at_vertex(m, ring[i], n, ring.data());
          if (C::is_smooth(children[i]))
            ASSERT_EQ(ours, 0.0f);
          else if (C::is_infinite(children[i]))
            ASSERT_EQ(ours, infinitely_sharp);
          else
            ASSERT_EQ(ours, children[i]);
        }
      }
    }
  }
  EXPECT_GT(compared, 50000);
}

TEST(CreaseOpenSubdiv, VertexRule)
{
  std::mt19937 rng(4);
  const Sdc::Crease osd;
  for (float vs : sharpness_values()) {
    for (unsigned n = 0; n <= 10; ++n) {
      EXPECT_EQ(C::vertex_rule(vs, n), from_osd(osd.DetermineVertexVertexRule(vs, int(n))));
      for (int trial = 0; trial < 50 && n > 0; ++trial) {
        const std::vector<float> ring = random_ring(rng, n);
        EXPECT_EQ(C::vertex_rule(vs, n, ring.data()),
                  from_osd(osd.DetermineVertexVertexRule(vs, int(n), ring.data())));
      }
    }
  }
}

// Parent and child rings as the refiner makes them: the child from the decay
// functions above, uniform or Chaikin. (OpenSubdiv does not take any child
// ring as given: it counts an edge by its own decay of the parent.)
TEST(CreaseOpenSubdiv, FractionalWeight)
{
  std::mt19937 rng(5);
  int blended = 0;
  for (Crease_method m : {Crease_method::uniform, Crease_method::chaikin}) {
    const Sdc::Crease osd = osd_crease(m);
    for (unsigned n = 1; n <= 10; ++n) {
      for (int trial = 0; trial < 500; ++trial) {
        const std::vector<float> parent = random_ring(rng, n);
        std::vector<float> child(n);
        for (unsigned i = 0; i < n; ++i)
          child[i] = C::subdivide_edge_sharpness_at_vertex(m, parent[i], n, parent.data());
        const float vs = sharpness_values()[std::size_t(trial) % sharpness_values().size()];
        const float child_vs = C::subdivide_vertex_sharpness(vs);
        const float ours = C::fractional_weight_at_vertex(vs, child_vs, n, parent.data(), child.data());
        const float theirs = osd.ComputeFractionalWeightAtVertex(vs, child_vs, int(n), parent.data(), child.data());
        ASSERT_EQ(ours, theirs) << "valence " << n << " trial " << trial;
        EXPECT_GE(ours, 0.0f);
        EXPECT_LE(ours, 1.0f);
        blended += ours > 0.0f && ours < 1.0f ? 1 : 0;
      }
    }
  }
  EXPECT_GT(blended, 100); // fractional weights were met, not only 0 and 1
}
#endif // CGAL_EXT_HAVE_OPENSUBDIV

} // namespace

} // namespace crease_tests
