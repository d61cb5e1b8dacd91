// Where the test meshes are; see test_util.h.
namespace test {
const char* data_directory() { return CGAL_EXT_TEST_DATA_DIR; }
} // namespace test
