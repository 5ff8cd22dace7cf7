#include "io/Hdf5File.hpp"

#include "core/Error.hpp"

#include <unistd.h>

#include <filesystem>
#include <limits>
#include <new>
#include <stdexcept>
#include <system_error>

namespace dpd {

namespace {

// HDF5 prints its whole error stack to stderr by default; we report through exceptions instead.
// The setting is per thread in thread-safe builds, so every file object repeats it.
void silenceHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// File-access properties shared by reader and writer. HDF5's file locks protect a file while it is
// being written; our temporary-and-rename protocol already guarantees that, and the locks fail
// outright on some network file systems, so they are switched off where the library allows it.
Hdf5Handle fileAccessProperties() {
    Hdf5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if (H5_VERSION_GE(1, 10, 7) && !H5_VERSION_GE(1, 12, 0)) || H5_VERSION_GE(1, 12, 1)
    H5Pset_file_locking(fapl.get(), false, true);
#endif
    return fapl;
}

std::size_t elementCount(const std::vector<hsize_t>& dims) {
    std::size_t n = 1;
    for (hsize_t d : dims) n *= static_cast<std::size_t>(d);
    return n;
}

std::vector<hsize_t> shapeOf(hid_t space) {
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(rank > 0 ? rank : 0);
    if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
}

std::size_t pointCount(hid_t space) {
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    return n > 0 ? static_cast<std::size_t>(n) : 0;
}

// Room for the n values a dataset or attribute declares; a damaged file can declare more than any
// machine holds, which is then its error, not an allocator's.
template <class T>
std::vector<T> valuesFor(std::size_t n, const std::string& path, const std::string& what) {
    try {
        return std::vector<T>(n);
    } catch (const std::length_error&) {
    } catch (const std::bad_alloc&) {
    }
    throw IoError(path + ": " + what + " declares " + std::to_string(n) +
                  " values, more than this machine can hold (is the file damaged?)");
}

// Variable-length UTF-8 string type: what h5py writes for str, and reads back as str.
Hdf5Handle variableStringType() {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    return type;
}

std::string shapeText(const std::vector<hsize_t>& dims) {
    std::string s = "(";
    for (std::size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
    return s + ")";
}

// Reading with an integer memory type from a floating-point file type would silently truncate.
bool convertible(hid_t fileType, hid_t memType) {
    const H5T_class_t fileClass = H5Tget_class(fileType);
    const H5T_class_t memClass = H5Tget_class(memType);
    return fileClass == memClass || (memClass == H5T_FLOAT && fileClass == H5T_INTEGER);
}

std::string typeWord(hid_t memType) { return H5Tget_class(memType) == H5T_FLOAT ? "numbers" : "integers"; }

void reclaimVariableStrings(hid_t memType, hid_t space, void* buffer) {
#if H5_VERSION_GE(1, 12, 0)
    H5Treclaim(memType, space, H5P_DEFAULT, buffer);
#else
    H5Dvlen_reclaim(memType, space, H5P_DEFAULT, buffer);
#endif
}

std::string trimFixedString(const char* begin, std::size_t size, H5T_str_t padding) {
    std::size_t length = 0;
    while (length < size && begin[length] != '\0') ++length;
    if (padding == H5T_STR_SPACEPAD)
        while (length > 0 && begin[length - 1] == ' ') --length;
    return std::string(begin, length);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
        close();
        id_ = other.id_;
        closer_ = other.closer_;
        other.id_ = -1;
    }
    return *this;
}

bool Hdf5Handle::close() {
    if (id_ < 0) return true;
    const herr_t status = closer_(id_);
    id_ = -1;
    return status >= 0;
}

// Creation properties without HDF5's object time stamps: the same content gives the same bytes, so a
// restarted run's files compare equal (cmp) to those of a run never interrupted.
Hdf5Handle untimedCreation(hid_t propertyClass) {
    Hdf5Handle properties(H5Pcreate(propertyClass), H5Pclose);
    H5Pset_obj_track_times(properties.get(), false);
    return properties;
}

// ---------------------------------------------------------------------------------------------
Hdf5Writer::Hdf5Writer(std::string finalPath)
    : finalPath_(std::move(finalPath)), temporaryPath_(finalPath_ + ".tmp" + std::to_string(::getpid())) {
    silenceHdf5Errors();
    const Hdf5Handle fapl = fileAccessProperties();
    const Hdf5Handle fcpl = untimedCreation(H5P_FILE_CREATE);
    file_ = Hdf5Handle(H5Fcreate(temporaryPath_.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose);
    if (!file_.valid()) fail("cannot create temporary file '" + temporaryPath_ + "'");
}

Hdf5Writer::~Hdf5Writer() {
    if (committed_) return;
    file_.close();
    std::error_code ignored;  // a destructor must not throw; a leftover would only be a stray .tmp
    std::filesystem::remove(temporaryPath_, ignored);
}

void Hdf5Writer::fail(const std::string& message) const { throw IoError(finalPath_ + ": " + message); }

void Hdf5Writer::createParentGroups(const std::string& name) const {
    const Hdf5Handle groupProperties = untimedCreation(H5P_GROUP_CREATE);
    for (std::size_t slash = name.find('/', 1); slash != std::string::npos; slash = name.find('/', slash + 1)) {
        const std::string group = name.substr(0, slash);
        if (H5Lexists(file_.get(), group.c_str(), H5P_DEFAULT) > 0) continue;
        const Hdf5Handle created(H5Gcreate2(file_.get(), group.c_str(), H5P_DEFAULT, groupProperties.get(), H5P_DEFAULT),
                                 H5Gclose);
        if (!created.valid()) fail("cannot create group '" + group + "'");
    }
}

void Hdf5Writer::requireOpen(const std::string& what) const {
    if (!file_.valid()) fail("cannot write " + what + ": file already committed");
}

void Hdf5Writer::writeDataset(const std::string& name, hid_t memType, hid_t fileType, const void* data,
                              std::size_t count, std::vector<hsize_t> dims) {
    requireOpen("dataset '" + name + "'");
    if (dims.empty()) dims = {static_cast<hsize_t>(count)};
    if (elementCount(dims) != count)
        throw std::invalid_argument(finalPath_ + ": dataset '" + name + "': shape " + shapeText(dims) +
                                    " does not match " + std::to_string(count) + " values");
    const Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    createParentGroups(name);
    const Hdf5Handle datasetProperties = untimedCreation(H5P_DATASET_CREATE);
    const Hdf5Handle dataset(H5Dcreate2(file_.get(), name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                        datasetProperties.get(), H5P_DEFAULT),
                             H5Dclose);
    if (!dataset.valid()) fail("cannot create dataset '" + name + "'");
    // An empty vector may hand over a null pointer, which H5Dwrite rejects even for zero elements.
    if (count > 0 && H5Dwrite(dataset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail("cannot write dataset '" + name + "'");
}

void Hdf5Writer::writeDoubles(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> dims) {
    writeDataset(name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data.data(), data.size(), std::move(dims));
}

void Hdf5Writer::writeUInt64(const std::string& name, const std::vector<std::uint64_t>& data,
                             std::vector<hsize_t> dims) {
    writeUInt64(name, data.data(), data.size(), std::move(dims));
}

void Hdf5Writer::writeUInt64(const std::string& name, const std::uint64_t* data, std::size_t count,
                             std::vector<hsize_t> dims) {
    writeDataset(name, H5T_NATIVE_UINT64, H5T_STD_U64LE, data, count, std::move(dims));
}

void Hdf5Writer::writeInt64(const std::string& name, const std::vector<std::int64_t>& data,
                            std::vector<hsize_t> dims) {
    writeDataset(name, H5T_NATIVE_INT64, H5T_STD_I64LE, data.data(), data.size(), std::move(dims));
}

void Hdf5Writer::writeInt32(const std::string& name, const std::vector<std::int32_t>& data,
                            std::vector<hsize_t> dims) {
    writeDataset(name, H5T_NATIVE_INT32, H5T_STD_I32LE, data.data(), data.size(), std::move(dims));
}

void Hdf5Writer::writeUInt8(const std::string& name, const std::vector<std::uint8_t>& data,
                            std::vector<hsize_t> dims) {
    writeDataset(name, H5T_NATIVE_UINT8, H5T_STD_U8LE, data.data(), data.size(), std::move(dims));
}

void Hdf5Writer::writeAttributeData(const std::string& objectPath, const std::string& attrName, hid_t memType,
                                    hid_t fileType, const void* data, std::size_t count, bool scalar) {
    const std::string what = "attribute '" + attrName + "' on '" + objectPath + "'";
    requireOpen(what);
    const Hdf5Handle object(H5Oopen(file_.get(), objectPath.c_str(), H5P_DEFAULT), H5Oclose);
    if (!object.valid()) fail("cannot write " + what + ": no object '" + objectPath + "'");
    if (H5Aexists(object.get(), attrName.c_str()) > 0) H5Adelete(object.get(), attrName.c_str());
    const hsize_t n = count;
    const Hdf5Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
    const Hdf5Handle attribute(H5Acreate2(object.get(), attrName.c_str(), fileType, space.get(), H5P_DEFAULT,
                                          H5P_DEFAULT),
                               H5Aclose);
    if (!attribute.valid()) fail("cannot create " + what);
    if (count > 0 && H5Awrite(attribute.get(), memType, data) < 0) fail("cannot write " + what);
}

// File types are fixed little-endian ones, like the datasets', so files are identical on every host.
void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName, double value) {
    writeAttributeData(objectPath, attrName, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, &value, 1, true);
}

void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName, std::int64_t value) {
    writeAttributeData(objectPath, attrName, H5T_NATIVE_INT64, H5T_STD_I64LE, &value, 1, true);
}

void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName,
                                const std::string& value) {
    const Hdf5Handle type = variableStringType();
    const char* pointer = value.c_str();
    writeAttributeData(objectPath, attrName, type.get(), type.get(), &pointer, 1, true);
}

void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName,
                                const std::vector<double>& values) {
    writeAttributeData(objectPath, attrName, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, values.data(), values.size(), false);
}

void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName,
                                const std::vector<std::int64_t>& values) {
    writeAttributeData(objectPath, attrName, H5T_NATIVE_INT64, H5T_STD_I64LE, values.data(), values.size(), false);
}

void Hdf5Writer::writeAttribute(const std::string& objectPath, const std::string& attrName,
                                const std::vector<std::string>& values) {
    const Hdf5Handle type = variableStringType();
    std::vector<const char*> pointers;
    for (const auto& v : values) pointers.push_back(v.c_str());
    writeAttributeData(objectPath, attrName, type.get(), type.get(), pointers.data(), pointers.size(), false);
}

void Hdf5Writer::commit() {
    requireOpen("file");
    if (!file_.close()) fail("cannot finish temporary file '" + temporaryPath_ + "'");
    std::error_code error;
    std::filesystem::rename(temporaryPath_, finalPath_, error);
    if (error) fail("cannot rename '" + temporaryPath_ + "' to it: " + error.message());
    committed_ = true;
}

// ---------------------------------------------------------------------------------------------
Hdf5Reader::Hdf5Reader(std::string path) : path_(std::move(path)) {
    silenceHdf5Errors();
    std::error_code error;
    if (!std::filesystem::exists(path_, error)) fail("no such file");
    const Hdf5Handle fapl = fileAccessProperties();
    file_ = Hdf5Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
    if (!file_.valid()) fail("cannot open as an HDF5 file");
}

void Hdf5Reader::fail(const std::string& message) const { throw IoError(path_ + ": " + message); }

bool Hdf5Reader::has(const std::string& name) const {
    std::string path = name;
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    if (path.empty() || path == "/") return true;
    // H5Lexists fails instead of answering "no" when an intermediate group is missing, so every
    // prefix is checked in turn.
    for (std::size_t slash = path.find('/', 1); slash != std::string::npos; slash = path.find('/', slash + 1))
        if (H5Lexists(file_.get(), path.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
    if (H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) <= 0) return false;
    return H5Oexists_by_name(file_.get(), path.c_str(), H5P_DEFAULT) > 0;  // soft links may dangle
}

bool Hdf5Reader::hasAttribute(const std::string& objectPath, const std::string& attrName) const {
    return has(objectPath) &&
           H5Aexists_by_name(file_.get(), objectPath.c_str(), attrName.c_str(), H5P_DEFAULT) > 0;
}

Hdf5Handle Hdf5Reader::openDataset(const std::string& name) const {
    if (!has(name)) fail("no dataset '" + name + "'");
    Hdf5Handle dataset(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) fail("'" + name + "' is not a dataset");
    return dataset;
}

template <class T>
std::vector<T> Hdf5Reader::readNumeric(const std::string& name, hid_t memType, std::vector<hsize_t>* dims) const {
    const Hdf5Handle dataset = openDataset(name);
    const Hdf5Handle fileType(H5Dget_type(dataset.get()), H5Tclose);
    if (!convertible(fileType.get(), memType)) fail("dataset '" + name + "' does not hold " + typeWord(memType));
    const Hdf5Handle space(H5Dget_space(dataset.get()), H5Sclose);
    std::vector<T> values = valuesFor<T>(pointCount(space.get()), path_, "dataset '" + name + "'");
    if (!values.empty() && H5Dread(dataset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        fail("cannot read dataset '" + name + "'");
    if (dims) *dims = shapeOf(space.get());
    return values;
}

std::vector<double> Hdf5Reader::readDoubles(const std::string& name, std::vector<hsize_t>* dims) const {
    return readNumeric<double>(name, H5T_NATIVE_DOUBLE, dims);
}

std::vector<std::uint64_t> Hdf5Reader::readUInt64(const std::string& name, std::vector<hsize_t>* dims) const {
    return readNumeric<std::uint64_t>(name, H5T_NATIVE_UINT64, dims);
}

std::vector<std::int64_t> Hdf5Reader::readInt64(const std::string& name, std::vector<hsize_t>* dims) const {
    return readNumeric<std::int64_t>(name, H5T_NATIVE_INT64, dims);
}

std::vector<std::int32_t> Hdf5Reader::readInt32(const std::string& name, std::vector<hsize_t>* dims) const {
    return readNumeric<std::int32_t>(name, H5T_NATIVE_INT32, dims);
}

std::vector<std::uint8_t> Hdf5Reader::readUInt8(const std::string& name, std::vector<hsize_t>* dims) const {
    return readNumeric<std::uint8_t>(name, H5T_NATIVE_UINT8, dims);
}

Hdf5Handle Hdf5Reader::openAttribute(const std::string& objectPath, const std::string& attrName) const {
    if (!has(objectPath)) fail("no object '" + objectPath + "' (looking for attribute '" + attrName + "')");
    if (!hasAttribute(objectPath, attrName)) fail("no attribute '" + attrName + "' on '" + objectPath + "'");
    Hdf5Handle attribute(
        H5Aopen_by_name(file_.get(), objectPath.c_str(), attrName.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attribute.valid()) fail("cannot open attribute '" + attrName + "' on '" + objectPath + "'");
    return attribute;
}

template <class T>
std::vector<T> Hdf5Reader::readAttributeNumbers(const std::string& objectPath, const std::string& attrName,
                                                hid_t memType) const {
    const Hdf5Handle attribute = openAttribute(objectPath, attrName);
    const Hdf5Handle fileType(H5Aget_type(attribute.get()), H5Tclose);
    if (!convertible(fileType.get(), memType))
        fail("attribute '" + attrName + "' on '" + objectPath + "' does not hold " + typeWord(memType));
    const Hdf5Handle space(H5Aget_space(attribute.get()), H5Sclose);
    std::vector<T> values = valuesFor<T>(pointCount(space.get()), path_, "attribute '" + attrName + "'");
    if (!values.empty() && H5Aread(attribute.get(), memType, values.data()) < 0)
        fail("cannot read attribute '" + attrName + "' on '" + objectPath + "'");
    return values;
}

void Hdf5Reader::requireSingleValue(std::size_t count, const std::string& objectPath,
                                    const std::string& attrName) const {
    if (count != 1)
        fail("attribute '" + attrName + "' on '" + objectPath + "' has " + std::to_string(count) +
             " values, expected one");
}

double Hdf5Reader::attributeDouble(const std::string& objectPath, const std::string& attrName) const {
    const std::vector<double> values = attributeDoubles(objectPath, attrName);
    requireSingleValue(values.size(), objectPath, attrName);
    return values.front();
}

std::int64_t Hdf5Reader::attributeInt(const std::string& objectPath, const std::string& attrName) const {
    const std::vector<std::int64_t> values = attributeInts(objectPath, attrName);
    requireSingleValue(values.size(), objectPath, attrName);
    return values.front();
}

std::vector<double> Hdf5Reader::attributeDoubles(const std::string& objectPath, const std::string& attrName) const {
    return readAttributeNumbers<double>(objectPath, attrName, H5T_NATIVE_DOUBLE);
}

std::vector<std::int64_t> Hdf5Reader::attributeInts(const std::string& objectPath,
                                                    const std::string& attrName) const {
    return readAttributeNumbers<std::int64_t>(objectPath, attrName, H5T_NATIVE_INT64);
}

std::string Hdf5Reader::attributeString(const std::string& objectPath, const std::string& attrName) const {
    const std::vector<std::string> values = attributeStrings(objectPath, attrName);
    requireSingleValue(values.size(), objectPath, attrName);
    return values.front();
}

std::vector<std::string> Hdf5Reader::attributeStrings(const std::string& objectPath,
                                                      const std::string& attrName) const {
    const std::string what = "attribute '" + attrName + "' on '" + objectPath + "'";
    const Hdf5Handle attribute = openAttribute(objectPath, attrName);
    // Reading with the file's own string type keeps its character set and padding; HDF5 only
    // converts between string types of the same kind.
    const Hdf5Handle type(H5Aget_type(attribute.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING) fail(what + " does not hold strings");
    const Hdf5Handle space(H5Aget_space(attribute.get()), H5Sclose);
    const std::size_t n = pointCount(space.get());
    std::vector<std::string> values;
    if (n == 0) return values;
    if (H5Tis_variable_str(type.get()) > 0) {
        std::vector<char*> pointers = valuesFor<char*>(n, path_, what);
        if (H5Aread(attribute.get(), type.get(), pointers.data()) < 0) fail("cannot read " + what);
        for (const char* p : pointers) values.emplace_back(p ? p : "");
        reclaimVariableStrings(type.get(), space.get(), pointers.data());
    } else {
        const std::size_t size = H5Tget_size(type.get());
        if (size == 0 || n > std::numeric_limits<std::size_t>::max() / size) fail(what + " has a damaged string size");
        std::vector<char> buffer = valuesFor<char>(n * size, path_, what);
        if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) fail("cannot read " + what);
        const H5T_str_t padding = H5Tget_strpad(type.get());
        for (std::size_t i = 0; i < n; ++i) values.push_back(trimFixedString(&buffer[i * size], size, padding));
    }
    return values;
}

}  // namespace dpd
