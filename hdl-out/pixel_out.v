

module pixel_out(clock,inp$valid,inp$ready,inp$x,inp$y,inp$z,inp$rgb0,inp$rgb1,inp$rgb2,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$x;
    input wire  [9:0] inp$y;
    input wire  [15:0] inp$z;
    input wire  [7:0] inp$rgb0;
    input wire  [7:0] inp$rgb1;
    input wire  [7:0] inp$rgb2;
    input wire  mem$ready;
    output reg  mem$rd_en;
    output reg  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output reg  mem$wr_en;
    output reg  [19:0] mem$wr_addr;
    output reg  [15:0] mem$wr_z;
    output reg  [23:0] mem$wr_rgb;
    output reg  idle;
    
    // Stub signals
    wire  depth_test$on;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [19:0] s1_addr$d;
    wire  [19:0] s1_addr$q;
    reg  s1_addr$clock;
    reg  [15:0] s1_z$d;
    wire  [15:0] s1_z$q;
    reg  s1_z$clock;
    reg  [23:0] s1_rgb$d;
    wire  [23:0] s1_rgb$q;
    reg  s1_rgb$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_write$d;
    wire  s2_write$q;
    reg  s2_write$clock;
    reg  [19:0] s2_addr$d;
    wire  [19:0] s2_addr$q;
    reg  s2_addr$clock;
    reg  [15:0] s2_z$d;
    wire  [15:0] s2_z$q;
    reg  s2_z$clock;
    reg  [23:0] s2_rgb$d;
    wire  [23:0] s2_rgb$q;
    reg  s2_rgb$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [15:0] s3_z$d;
    wire  [15:0] s3_z$q;
    reg  s3_z$clock;
    reg  hit2$d;
    wire  hit2$q;
    reg  hit2$clock;
    reg  hit3$d;
    wire  hit3$q;
    reg  hit3$clock;
    reg  [9:0] addr$hi;
    reg  [9:0] addr$lo;
    wire  [19:0] addr$out;
    reg  [7:0] rg$hi;
    reg  [7:0] rg$lo;
    wire  [15:0] rg$out;
    reg  [15:0] rgb$hi;
    reg  [7:0] rgb$lo;
    wire  [23:0] rgb$out;
    
    // Local signals
    reg  [15:0] old_z;
    reg  pass;
    
    // Sub module instances
    pixel_out$depth_test depth_test(
        .on(depth_test$on)
    );
    pixel_out$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    pixel_out$s1_addr s1_addr(
        .d(s1_addr$d),
        .q(s1_addr$q),
        .clock(s1_addr$clock)
    );
    pixel_out$s1_z s1_z(
        .d(s1_z$d),
        .q(s1_z$q),
        .clock(s1_z$clock)
    );
    pixel_out$s1_rgb s1_rgb(
        .d(s1_rgb$d),
        .q(s1_rgb$q),
        .clock(s1_rgb$clock)
    );
    pixel_out$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    pixel_out$s2_write s2_write(
        .d(s2_write$d),
        .q(s2_write$q),
        .clock(s2_write$clock)
    );
    pixel_out$s2_addr s2_addr(
        .d(s2_addr$d),
        .q(s2_addr$q),
        .clock(s2_addr$clock)
    );
    pixel_out$s2_z s2_z(
        .d(s2_z$d),
        .q(s2_z$q),
        .clock(s2_z$clock)
    );
    pixel_out$s2_rgb s2_rgb(
        .d(s2_rgb$d),
        .q(s2_rgb$q),
        .clock(s2_rgb$clock)
    );
    pixel_out$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    pixel_out$s3_z s3_z(
        .d(s3_z$d),
        .q(s3_z$q),
        .clock(s3_z$clock)
    );
    pixel_out$hit2 hit2(
        .d(hit2$d),
        .q(hit2$q),
        .clock(hit2$clock)
    );
    pixel_out$hit3 hit3(
        .d(hit3$d),
        .q(hit3$q),
        .clock(hit3$clock)
    );
    pixel_out$addr addr(
        .hi(addr$hi),
        .lo(addr$lo),
        .out(addr$out)
    );
    pixel_out$rg rg(
        .hi(rg$hi),
        .lo(rg$lo),
        .out(rg$out)
    );
    pixel_out$rgb rgb(
        .hi(rgb$hi),
        .lo(rgb$lo),
        .out(rgb$out)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_addr$clock = clock;
        s1_z$clock = clock;
        s1_rgb$clock = clock;
        s2_valid$clock = clock;
        s2_write$clock = clock;
        s2_addr$clock = clock;
        s2_z$clock = clock;
        s2_rgb$clock = clock;
        s3_valid$clock = clock;
        s3_z$clock = clock;
        hit2$clock = clock;
        hit3$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_addr$d = s1_addr$q;
        s1_z$d = s1_z$q;
        s1_rgb$d = s1_rgb$q;
        s2_valid$d = s2_valid$q;
        s2_write$d = s2_write$q;
        s2_addr$d = s2_addr$q;
        s2_z$d = s2_z$q;
        s2_rgb$d = s2_rgb$q;
        s3_valid$d = s3_valid$q;
        s3_z$d = s3_z$q;
        hit2$d = hit2$q;
        hit3$d = hit3$q;
        addr$hi = inp$y;
        addr$lo = inp$x;
        rg$hi = inp$rgb0;
        rg$lo = inp$rgb1;
        rgb$hi = rg$out;
        rgb$lo = inp$rgb2;
        inp$ready = mem$ready;
        mem$rd_en = inp$valid & depth_test$on;
        mem$rd_addr = addr$out;
        old_z = mem$rd_z;
        if (s3_valid$q & hit3$q) begin
            old_z = s3_z$q;
        end
        if (s2_write$q & hit2$q) begin
            old_z = s2_z$q;
        end
        pass = s1_valid$q;
        if (depth_test$on & (s1_z$q >= old_z)) begin
            pass = 1'b0;
        end
        mem$wr_en = s2_write$q;
        mem$wr_addr = s2_addr$q;
        mem$wr_z = s2_z$q;
        mem$wr_rgb = s2_rgb$q;
        idle = ~s1_valid$q & ~s2_valid$q;
        if (mem$ready) begin
            s1_valid$d = inp$valid;
            s1_addr$d = addr$out;
            s1_z$d = inp$z;
            s1_rgb$d = rgb$out;
            hit2$d = s1_addr$q == addr$out;
            hit3$d = s2_addr$q == addr$out;
            s2_valid$d = s1_valid$q;
            s2_write$d = pass;
            s2_addr$d = s1_addr$q;
            s2_z$d = s1_z$q;
            s2_rgb$d = s1_rgb$q;
            s3_valid$d = s2_write$q;
            s3_z$d = s2_z$q;
        end
    end
    
endmodule // pixel_out


module pixel_out$addr(hi,lo,out);
    
    // Module arguments
    input wire  [9:0] hi;
    input wire  [9:0] lo;
    output reg  [19:0] out;
    
    // Constant declarations
    localparam  shift = 8'ha;
    
    // Update code
    always @(*) begin
        out = (((hi) & 20'hfffff) << shift) | ((lo) & 20'hfffff);
    end
    
endmodule // pixel_out$addr


module pixel_out$depth_test(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // pixel_out$depth_test


module pixel_out$hit2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$hit2


module pixel_out$hit3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$hit3


module pixel_out$rg(hi,lo,out);
    
    // Module arguments
    input wire  [7:0] hi;
    input wire  [7:0] lo;
    output reg  [15:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 16'hffff) << shift) | ((lo) & 16'hffff);
    end
    
endmodule // pixel_out$rg


module pixel_out$rgb(hi,lo,out);
    
    // Module arguments
    input wire  [15:0] hi;
    input wire  [7:0] lo;
    output reg  [23:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 24'hffffff) << shift) | ((lo) & 24'hffffff);
    end
    
endmodule // pixel_out$rgb


module pixel_out$s1_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s1_addr


module pixel_out$s1_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s1_rgb


module pixel_out$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s1_valid


module pixel_out$s1_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s1_z


module pixel_out$s2_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s2_addr


module pixel_out$s2_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s2_rgb


module pixel_out$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s2_valid


module pixel_out$s2_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s2_write


module pixel_out$s2_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s2_z


module pixel_out$s3_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s3_valid


module pixel_out$s3_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // pixel_out$s3_z
