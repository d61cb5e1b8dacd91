// The huge-page allocator of the large arrays: which blocks are advised, that
// values survive growth across the size threshold, and that the kernel got
// the advice (the VMA flag it sets, read back from /proc/self/smaps). Leaks
// and mismatched frees are the sanitizers' to report.
#include <CGAL_ext/Mobius_mesh/internal/Property_container.h>
#include <CGAL_ext/internal/Huge_page_allocator.h>
#include <CGAL_ext/internal/Uninitialized_array.h>

#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace huge_page_allocator_tests {

namespace {

using CGAL_ext::internal::can_advise_huge_pages;
using CGAL_ext::internal::Huge_page_allocator;
using CGAL_ext::internal::Huge_page_vector;
using CGAL_ext::internal::huge_page_bytes;

constexpr std::size_t mib = std::size_t(1) << 20;

// The first whole huge page inside [p, p + bytes), or null if none fits:
// what the allocator's advice covers.
const char* first_whole_huge_page(const void* p, std::size_t bytes)
{
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t begin = (a + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  return begin + huge_page_bytes <= a + bytes ? reinterpret_cast<const char*>(begin) : nullptr;
}

// The VmFlags of the mapping of /proc/self/smaps that holds `p` ("" if none).
std::string mapping_flags(const void* p)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = begin <= a && a < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return "";
}

// Transparent huge pages compiled into the kernel (enabled or not): then
// madvise(MADV_HUGEPAGE) is accepted and marks the mapping "hg".
bool kernel_has_thp() { return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good(); }

TEST(HugePageAllocator, IsAStatelessStandardAllocator)
{
  using A = Huge_page_allocator<std::uint32_t>;
  static_assert(std::allocator_traits<A>::is_always_equal::value);
  static_assert(std::is_same_v<std::allocator_traits<A>::rebind_alloc<double>, Huge_page_allocator<double>>);
  EXPECT_TRUE(A() == Huge_page_allocator<double>());
  EXPECT_FALSE(A() != A());
  // Swapping and moving between vectors keep the buffers: allocators are equal.
  Huge_page_vector<std::uint32_t> a(3 * mib / 4, 7), b;
  const std::uint32_t* buffer = a.data();
  b = std::move(a);
  EXPECT_EQ(b.data(), buffer);
}

TEST(HugePageAllocator, SmallBlocksAreOrdinary)
{
  Huge_page_vector<std::uint64_t> v(1000);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = i * i;
  EXPECT_FALSE(Huge_page_allocator<std::uint64_t>::is_large(v.capacity()));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % alignof(std::uint64_t), 0u);
  for (std::size_t i = 0; i < v.size(); ++i)
    ASSERT_EQ(v[i], i * i);
}

TEST(HugePageAllocator, LargeBlocksAreAdvisedWhereWholeHugePagesFit)
{
  // Exactly at the threshold, above it, and of an element size that does not
  // divide a huge page: ordinary blocks (not aligned: arrays at one offset
  // modulo 4 KiB slow down loops over several of them), advised inside.
  struct Triple
  {
    double x, y, z;
  };
  Huge_page_vector<std::uint8_t> at(huge_page_bytes);
  Huge_page_vector<std::uint32_t> above(5 * mib);
  Huge_page_vector<Triple> odd(huge_page_bytes / sizeof(Triple) + 1);
  EXPECT_EQ(at[0] + at.back() + above[0] + above.back(), 0u); // value-initialised
  EXPECT_EQ(odd.back().x + odd.back().z, 0.0);
  EXPECT_EQ(Huge_page_allocator<std::uint8_t>::is_large(at.size()), can_advise_huge_pages);
  EXPECT_EQ(Huge_page_allocator<Triple>::is_large(odd.size()), can_advise_huge_pages);
  // One element less than a huge page: not advised.
  EXPECT_FALSE(Huge_page_allocator<std::uint8_t>::is_large(huge_page_bytes - 1));
  if (can_advise_huge_pages && kernel_has_thp()) {
    const char* page = first_whole_huge_page(above.data(), above.size() * sizeof(std::uint32_t));
    ASSERT_NE(page, nullptr);
    EXPECT_NE(mapping_flags(page).find(" hg"), std::string::npos) << mapping_flags(page);
  }
}

TEST(HugePageAllocator, ValuesSurviveGrowthAcrossTheThreshold)
{
  // push_back doubles the capacity from ordinary blocks to huge-page ones,
  // then from huge-page blocks to larger ones.
  Huge_page_vector<std::uint32_t> v;
  const std::uint32_t n = std::uint32_t(6 * mib);
  bool crossed = false;
  for (std::uint32_t i = 0; i < n; ++i) {
    const bool large_before = Huge_page_allocator<std::uint32_t>::is_large(v.capacity());
    v.push_back(i ^ 0x9e3779b9u);
    crossed |= !large_before && Huge_page_allocator<std::uint32_t>::is_large(v.capacity());
  }
  EXPECT_EQ(crossed, can_advise_huge_pages);
  for (std::uint32_t i = 0; i < n; ++i)
    ASSERT_EQ(v[i], i ^ 0x9e3779b9u);
  // And back down: shrinking to a small block keeps the values too.
  v.resize(100);
  v.shrink_to_fit();
  for (std::uint32_t i = 0; i < 100; ++i)
    ASSERT_EQ(v[i], i ^ 0x9e3779b9u);
}

TEST(HugePageAllocator, UninitializedArraysAreOnHugePagesToo)
{
  CGAL_ext::internal::Uninitialized_array<std::uint32_t> a;
  a.resize(mib);
  if (can_advise_huge_pages && kernel_has_thp()) {
    const char* page = first_whole_huge_page(a.data(), a.size() * sizeof(std::uint32_t));
    ASSERT_NE(page, nullptr); // 4 MiB hold a whole huge page wherever they start
    EXPECT_NE(mapping_flags(page).find(" hg"), std::string::npos) << mapping_flags(page);
  }
  for (std::uint32_t i = 0; i < a.size(); ++i)
    a[i] = i;
  a.resize(3 * mib); // the first values move to the new block
  for (std::uint32_t i = 0; i < mib; ++i)
    ASSERT_EQ(a[i], i);
}

TEST(HugePageAllocator, TheKernelIsAdvised)
{
  if (!can_advise_huge_pages || !kernel_has_thp())
    GTEST_SKIP() << "no transparent huge pages here";
  Huge_page_vector<std::uint32_t> v(4 * mib);
  EXPECT_NE(mapping_flags(v.data() + v.size() / 2).find(" hg"), std::string::npos) << mapping_flags(v.data());
  // The control: a fresh mapping of the same size is found, not advised (a
  // block from the heap could reuse pages an earlier block had advised).
  const std::size_t bytes = 4 * mib * sizeof(std::uint32_t);
  void* plain = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(plain, MAP_FAILED);
  const std::string plain_flags = mapping_flags(static_cast<char*>(plain) + bytes / 2);
  ::munmap(plain, bytes);
  EXPECT_NE(plain_flags.find("VmFlags:"), std::string::npos);
  EXPECT_EQ(plain_flags.find(" hg"), std::string::npos) << plain_flags;
}

TEST(HugePageAllocator, PropertyArraysGrowOntoAdvisedPages)
{
  // Property arrays stay std::vectors (their type is visible through
  // Property_map::data()); only the huge pages inside their fresh part are advised.
  static_assert(std::is_same_v<decltype(std::declval<CGAL_ext::internal::Property_array<double>&>().data()),
                               std::vector<double>&>);
  CGAL_ext::internal::Property_array<double> a("p", -1.0);
  a.resize(10);
  for (std::size_t i = 0; i < 10; ++i)
    a[i] = double(i);
  a.resize(2 * mib);
  for (std::size_t i = 0; i < 10; ++i)
    ASSERT_EQ(a[i], double(i));
  for (std::size_t i = 10; i < 2 * mib; ++i)
    ASSERT_EQ(a[i], -1.0);
  if (can_advise_huge_pages && kernel_has_thp()) {
    EXPECT_NE(mapping_flags(&a[mib]).find(" hg"), std::string::npos) << mapping_flags(&a[mib]);
  }
}

} // namespace

} // namespace huge_page_allocator_tests
