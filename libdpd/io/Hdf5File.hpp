#pragma once
// A small RAII layer over the HDF5 C API, just wide enough for snapshots and sampled fields.
//
// Writing is all-or-nothing: Hdf5Writer fills "<finalPath>.tmp<pid>" and commit() renames it over
// finalPath, so a reader (ParaView, h5py, a restart) sees either the previous file or the complete
// new one, never a half-written file. Without commit() the temporary file is removed.
//
// Reading reports every problem (missing file, dataset, attribute, wrong type) as dpd::IoError
// naming the file and the item; HDF5's own error-stack printing is switched off so that a missing
// dataset produces one clear message instead of a screenful of library internals.
//
// Names of datasets may contain groups ("particles/position"); the writer creates the intermediate
// groups. Attributes hang on an object path, "/" being the root group.
#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

// Owns one HDF5 identifier and closes it with the matching H5?close function. Move-only.
class Hdf5Handle {
public:
    using Closer = herr_t (*)(hid_t);

    Hdf5Handle() = default;
    Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle() { close(); }

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    // Closes now; false when HDF5 reports a failure (closing a file flushes it, which can fail).
    bool close();

private:
    hid_t id_ = -1;
    Closer closer_ = nullptr;
};

class Hdf5Writer {
public:
    // Creates the temporary file next to finalPath; IoError when that is impossible.
    explicit Hdf5Writer(std::string finalPath);
    ~Hdf5Writer();  // removes the temporary file unless committed
    Hdf5Writer(const Hdf5Writer&) = delete;
    Hdf5Writer& operator=(const Hdf5Writer&) = delete;

    const std::string& path() const { return finalPath_; }
    const std::string& temporaryPath() const { return temporaryPath_; }

    // dims defaults to {data.size()}; otherwise its product must equal data.size()
    // (std::invalid_argument). Data are row-major, as numpy and h5py expect.
    void writeDoubles(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> dims = {});
    void writeUInt64(const std::string& name, const std::vector<std::uint64_t>& data, std::vector<hsize_t> dims = {});
    // The same from `count` values at `data`, for arrays held otherwise (the particles' ids, in
    // huge-page vectors), without a copy.
    void writeUInt64(const std::string& name, const std::uint64_t* data, std::size_t count, std::vector<hsize_t> dims = {});
    void writeInt64(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> dims = {});
    void writeInt32(const std::string& name, const std::vector<std::int32_t>& data, std::vector<hsize_t> dims = {});
    void writeUInt8(const std::string& name, const std::vector<std::uint8_t>& data, std::vector<hsize_t> dims = {});

    // Attributes on an existing object ("/" = root). Writing an attribute again replaces it.
    // Strings are stored as variable-length UTF-8, which h5py returns as str.
    void writeAttribute(const std::string& objectPath, const std::string& attrName, double value);
    void writeAttribute(const std::string& objectPath, const std::string& attrName, std::int64_t value);
    void writeAttribute(const std::string& objectPath, const std::string& attrName, int value) {
        writeAttribute(objectPath, attrName, static_cast<std::int64_t>(value));  // resolves int literals
    }
    void writeAttribute(const std::string& objectPath, const std::string& attrName, const std::string& value);
    void writeAttribute(const std::string& objectPath, const std::string& attrName, const char* value) {
        writeAttribute(objectPath, attrName, std::string(value));
    }
    void writeAttribute(const std::string& objectPath, const std::string& attrName, const std::vector<double>& values);
    void writeAttribute(const std::string& objectPath, const std::string& attrName,
                        const std::vector<std::int64_t>& values);
    void writeAttribute(const std::string& objectPath, const std::string& attrName,
                        const std::vector<std::string>& values);

    // Closes the file and renames it over finalPath. Nothing may be written afterwards.
    void commit();

private:
    void writeDataset(const std::string& name, hid_t memType, hid_t fileType, const void* data, std::size_t count,
                      std::vector<hsize_t> dims);
    // count == 1 with scalar == true gives a scalar attribute, anything else a 1-D one.
    void writeAttributeData(const std::string& objectPath, const std::string& attrName, hid_t memType,
                            hid_t fileType, const void* data, std::size_t count, bool scalar);
    void requireOpen(const std::string& what) const;
    void createParentGroups(const std::string& datasetName) const;  // without time stamps
    [[noreturn]] void fail(const std::string& message) const;

    std::string finalPath_;
    std::string temporaryPath_;
    Hdf5Handle file_;
    bool committed_ = false;
};

class Hdf5Reader {
public:
    explicit Hdf5Reader(std::string path);  // IoError when missing or not HDF5

    const std::string& path() const { return path_; }
    // True when a dataset or group of that name exists ("a/b/c" with any part missing is false).
    bool has(const std::string& name) const;
    bool hasAttribute(const std::string& objectPath, const std::string& attrName) const;

    // Whole dataset, flattened row-major; *dims receives its shape. Integer readers refuse
    // floating-point datasets (they would truncate); readDoubles accepts integer datasets.
    std::vector<double> readDoubles(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;
    std::vector<std::uint64_t> readUInt64(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;
    std::vector<std::int64_t> readInt64(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;
    std::vector<std::int32_t> readInt32(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;
    std::vector<std::uint8_t> readUInt8(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;

    // Scalar readers accept a scalar or a one-element attribute. Strings may be variable or
    // fixed length.
    double attributeDouble(const std::string& objectPath, const std::string& attrName) const;
    std::int64_t attributeInt(const std::string& objectPath, const std::string& attrName) const;
    std::string attributeString(const std::string& objectPath, const std::string& attrName) const;
    std::vector<double> attributeDoubles(const std::string& objectPath, const std::string& attrName) const;
    std::vector<std::int64_t> attributeInts(const std::string& objectPath, const std::string& attrName) const;
    std::vector<std::string> attributeStrings(const std::string& objectPath, const std::string& attrName) const;

private:
    template <class T>
    std::vector<T> readNumeric(const std::string& name, hid_t memType, std::vector<hsize_t>* dims) const;
    template <class T>
    std::vector<T> readAttributeNumbers(const std::string& objectPath, const std::string& attrName,
                                        hid_t memType) const;
    Hdf5Handle openDataset(const std::string& name) const;
    Hdf5Handle openAttribute(const std::string& objectPath, const std::string& attrName) const;
    void requireSingleValue(std::size_t count, const std::string& objectPath, const std::string& attrName) const;
    [[noreturn]] void fail(const std::string& message) const;

    std::string path_;
    Hdf5Handle file_;
};

}  // namespace dpd
