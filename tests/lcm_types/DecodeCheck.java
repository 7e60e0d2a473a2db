// Decodes each <type>.bin in a folder with the classes of touchline-types.jar, as lcm-spy
// does, and prints "<type> utime=<value>". Run: java -cp lcm.jar:touchline-types.jar DecodeCheck.java DIR
import java.io.File;
import java.nio.file.Files;
import java.util.Arrays;

public class DecodeCheck {
  public static void main(String[] args) throws Exception {
    File[] files = new File(args[0]).listFiles((d, name) -> name.endsWith(".bin"));
    Arrays.sort(files);
    for (File f : files) {
      String type = f.getName().replace(".bin", "");
      Class<?> c = Class.forName("touchline." + type);
      Object msg = c.getConstructor(byte[].class).newInstance((Object) Files.readAllBytes(f.toPath()));
      System.out.println(type + " utime=" + c.getField("utime").get(msg));
    }
  }
}
